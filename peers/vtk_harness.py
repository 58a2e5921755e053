"""VTK's vtkFixedPointVolumeRayCastMapper on a cube scene, for scripts/peers.

Usage: vtk_harness.py SCENE CAMERA_JSON REPEAT OUT.png [THREADS]

CAMERA_JSON is `cube render --arch reference --json`'s output: its
details.camera (right, up, forward, image centre, voxel lengths per pixel)
places VTK's parallel camera exactly where the scene's is, in dataset voxel
coordinates (VTK's volume has spacing 1 and origin 0). Opacity and colour
are the scene's piecewise-linear transfer function; shading its Phong
coefficients with one directional light, in camera space as the scene gives
it. Prints one JSON line with the medians of REPEAT runs: frame (a render
after the camera moved), tf_change (a render after the opacity function
changed) and prep (the first render, which builds the mapper's tables).
Renders offscreen (EGL when there is no display), on THREADS threads
(default: VTK's own choice, every core).
"""
import json
import os
import sys
import time

import vtk


def main(scene_path, camera_path, repeat, out, threads=None):
    s = json.load(open(scene_path))
    cam = json.load(open(camera_path))["details"]["camera"]
    v = s["volume"]
    nx, ny, nz = v["dims"]
    w, h = s["image"]
    raw = os.path.join(os.path.dirname(scene_path), v["raw"])
    reader = vtk.vtkImageReader()
    reader.SetFileName(raw)
    reader.SetDataScalarTypeToUnsignedChar()
    reader.SetNumberOfScalarComponents(1)
    reader.SetDataExtent(0, nx - 1, 0, ny - 1, 0, nz - 1)
    reader.SetDataSpacing(1, 1, 1)
    reader.SetDataOrigin(0, 0, 0)
    reader.SetFileDimensionality(3)
    # The raw file's first row is y = 0: no flip.
    reader.FileLowerLeftOn()
    reader.SetDataByteOrderToLittleEndian()
    reader.Update()

    t = s["transfer"]
    opacity = vtk.vtkPiecewiseFunction()

    def set_opacity():
        opacity.RemoveAllPoints()
        for x, a in t["opacity"]:
            opacity.AddPoint(x, a)

    set_opacity()
    colour = vtk.vtkColorTransferFunction()
    for x, r, g, b in t["color"]:
        colour.AddRGBPoint(x, r, g, b)
    prop = vtk.vtkVolumeProperty()
    prop.SetScalarOpacity(opacity)
    prop.SetColor(colour)
    prop.SetInterpolationTypeToLinear()
    # The scene's opacities are per voxel length, VTK's per unit distance.
    prop.SetScalarOpacityUnitDistance(1.0)
    sh = s.get("shading", {})
    if sh.get("enabled", True):
        prop.ShadeOn()
        prop.SetAmbient(sh.get("ambient", 0.25))
        prop.SetDiffuse(sh.get("diffuse", 0.6))
        prop.SetSpecular(sh.get("specular", 0.3))
        prop.SetSpecularPower(sh.get("shininess", 12))
    mapper = vtk.vtkFixedPointVolumeRayCastMapper()
    mapper.SetInputConnection(reader.GetOutputPort())
    mapper.SetSampleDistance(1.0)
    mapper.SetAutoAdjustSampleDistances(0)
    if threads is not None:
        mapper.SetNumberOfThreads(threads)
    volume = vtk.vtkVolume()
    volume.SetMapper(mapper)
    volume.SetProperty(prop)

    ren = vtk.vtkRenderer()
    ren.SetBackground(0, 0, 0)
    ren.AddVolume(volume)
    win = vtk.vtkRenderWindow()
    win.SetOffScreenRendering(1)
    win.AddRenderer(ren)
    win.SetSize(w, h)
    c = ren.GetActiveCamera()
    c.ParallelProjectionOn()
    o, f, up = cam["origin"], cam["forward"], cam["up"]
    dist = 4 * max(nx, ny, nz)
    c.SetFocalPoint(*o)
    c.SetPosition(*[o[i] - dist * f[i] for i in range(3)])
    c.SetViewUp(*up)
    # Parallel scale: half the image height in world units.
    c.SetParallelScale(cam["scale"] * h / 2)
    c.SetClippingRange(dist - 2 * max(nx, ny, nz), dist + 2 * max(nx, ny, nz))
    ren.RemoveAllLights()
    light = vtk.vtkLight()
    light.SetLightTypeToSceneLight()
    light.PositionalOff()
    lx, ly, lz = sh.get("light_dir", [0.3, 0.3, 1.0])
    r_, u_ = cam["right"], cam["up"]
    to_light = [r_[i] * lx + u_[i] * ly - f[i] * lz for i in range(3)]
    light.SetFocalPoint(*o)
    light.SetPosition(*[o[i] + to_light[i] for i in range(3)])
    light.SetIntensity(1.0)
    ren.AddLight(light)

    t0 = time.perf_counter()
    win.Render()
    prep = time.perf_counter() - t0
    frames, tfs = [], []
    for _ in range(repeat):
        c.Modified()
        volume.Modified()
        t0 = time.perf_counter()
        win.Render()
        frames.append(time.perf_counter() - t0)
    for _ in range(repeat):
        set_opacity()
        opacity.Modified()
        t0 = time.perf_counter()
        win.Render()
        tfs.append(time.perf_counter() - t0)
    grab = vtk.vtkWindowToImageFilter()
    grab.SetInput(win)
    grab.SetInputBufferTypeToRGB()
    grab.ReadFrontBufferOff()
    grab.Update()
    png = vtk.vtkPNGWriter()
    png.SetFileName(out)
    png.SetInputConnection(grab.GetOutputPort())
    png.Write()
    med = lambda x: sorted(x)[len(x) // 2]
    print(json.dumps({
        "prep_seconds": prep, "frame_seconds": med(frames), "tf_change_seconds": med(tfs),
        "threads": mapper.GetNumberOfThreads(), "version": vtk.vtkVersion.GetVTKVersion(),
    }))


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2], int(sys.argv[3]), sys.argv[4],
         int(sys.argv[5]) if len(sys.argv) > 5 else None)
