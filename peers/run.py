"""The peers run of scripts/peers (which installs and builds first).

Usage: run.py SCENE[,SCENE...] REPEAT OUT SIZES SCALING_SCENE

1. On each SCENE: VolPack (1 thread), VTK's vtkFixedPointVolumeRayCastMapper and
   every software path of the kit (the quantized projection and splatting,
   the Cube-4L and Cube-3 golden models), the kit's and VTK's at 1 thread
   and at every core. Each image is judged against the scene's float
   reference (`cube compare`, `--compare-reference`).
2. Pairs: the kit's renderers and the peer each is measured against, in
   turn, PAIRS rounds at every core (VolPack at 1 thread): the ratio of
   each round, then their median and range. On a machine whose speed
   drifts between the table's runs, a ratio of neighbouring runs holds
   where a ratio of runs minutes apart does not.
3. Scaling: SCALING_SCENE with the built-in phantom at each of SIZES (N³
   voxels), written raw by `cube volume` so that the peers read the same
   voxels, every renderer at every core. The exponent of time in voxels is
   a least-squares fit of log time on log voxels; memory is the peak
   resident set of the renderer's process at the largest size.

Writes OUT/peers.md and OUT/peers.json (each whole or not at all) and each
scene's images in OUT/<scene's file name>/. Ratios are time over the peer's time in
the same run (below 1: faster).
"""
import datetime
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile

CUBE = "target/release/cube"
VENV_PY = "target/peers/venv/bin/python"
VOLPACK = "target/peers/volpack_harness"
CORES = os.cpu_count()
# The kit's renderers: name, `cube render --arch`, and the quantized path's
# traversal order (None: the scene's own). Front to back the quantized
# projection ends rays early, as VolPack does.
KIT = [("quantized-projection", "quantized-projection", None),
       ("quantized-projection-f2b", "quantized-projection", "front_to_back"),
       ("quantized-splat", "quantized-splat", None),
       ("cube4l", "cube4l", None),
       ("cube3", "cube3", None)]


def fail(msg):
    sys.exit(f"scripts/peers: {msg}")


def run(cmd, env=None, rss=None):
    """Run cmd; returns stdout. With rss, the peak resident set (KiB) of the
    process goes into the list rss (from wait4: no tool needed)."""
    e = dict(os.environ, **(env or {}))
    with tempfile.TemporaryFile("w+") as out, tempfile.TemporaryFile("w+") as err:
        p = subprocess.Popen(cmd, env=e, stdout=out, stderr=err, text=True)
        _, status, usage = os.wait4(p.pid, 0)
        p.returncode = os.waitstatus_to_exitcode(status)
        out.seek(0)
        err.seek(0)
        if p.returncode != 0:
            fail(f"{' '.join(cmd[:4])}... failed:\n{err.read().strip()[-2000:]}")
        if rss is not None:
            rss.append(usage.ru_maxrss)
        return out.read()


def volpack_args(scene_path):
    """The scene's numbers for the VolPack harness."""
    s = json.load(open(scene_path))
    v = s["volume"]
    if "raw" not in v or v.get("type") != "u8" or "window" in v or "crop" in v:
        fail(f"{scene_path}: the scene needs a u8 raw volume without window or crop")
    view = s["view"]
    if view.get("projection") != "parallel":
        fail(f"{scene_path}: the scene needs a parallel view")
    if s.get("mode", "composite") != "composite":
        fail(f"{scene_path}: the scene needs composite mode")
    raw = os.path.join(os.path.dirname(scene_path), v["raw"])
    nx, ny, nz = v["dims"]
    rx, ry, rz = view.get("rotate_deg", [0, 0, 0])
    # Zoom 1 fits the volume's diagonal to the image; VolPack's object
    # units make the largest dimension 1.
    half = math.sqrt(nx * nx + ny * ny + nz * nz) / max(nx, ny, nz) / 2 / view.get("zoom", 1.0)
    w, h = s["image"]
    sh = s.get("shading", {})
    on = sh.get("enabled", True)
    t = s["transfer"]
    # VolPack's lookup shader indexes by normal alone: one material, the
    # mean of the transfer function's colours.
    col = [sum(c[i] for c in t["color"]) / len(t["color"]) for i in (1, 2, 3)]
    lx, ly, lz = sh.get("light_dir", [0.3, 0.3, 1.0])
    ramp = t["opacity"]
    head = [raw, nx, ny, nz, rx, ry, rz, half, w, h]
    tail = [sh.get("ambient", 0.25) if on else 1.0, sh.get("diffuse", 0.6) if on else 0.0,
            sh.get("specular", 0.3) if on else 0.0, sh.get("shininess", 12),
            # VolPack's eye x and y axes point opposite to the scene
            # camera's right and down (found against the reference image).
            -lx, -ly, lz, *col, len(ramp)]
    for x, a in ramp:
        tail += [round(x), a]
    return [str(a) for a in head], [str(a) for a in tail]


def volpack(scene, repeat, out_png, rss=None):
    head, tail = volpack_args(scene)
    ppm = out_png[:-4] + ".ppm"
    j = json.loads(run([VOLPACK, *head, str(repeat), ppm, *tail], rss=rss).strip().splitlines()[-1])
    run([sys.executable, "peers/ppm2png.py", ppm, out_png])
    os.unlink(ppm)
    return j


def vtk_camera(scene, tmp):
    cam = os.path.join(tmp, "camera.json")
    if os.path.exists(cam):
        os.unlink(cam)
    # The camera alone is wanted: the coarsest reference step is enough.
    run([CUBE, "render", "--scene", scene, "--arch", "reference", "--ref-step", "4", "--json", cam])
    return cam


def vtk(scene, cam, repeat, out_png, threads, rss=None):
    out = run([VENV_PY, "peers/vtk_harness.py", scene, cam, str(repeat), out_png, str(threads)], rss=rss)
    return json.loads(out.strip().splitlines()[-1])


def kit_scene(scene, order, tmp):
    """SCENE itself, or a copy in tmp with the quantized path's traversal
    order set (a raw volume's path made absolute)."""
    if order is None:
        return scene
    s = json.load(open(scene))
    v = s["volume"]
    if "raw" in v:
        v["raw"] = os.path.abspath(os.path.join(os.path.dirname(scene), v["raw"]))
    s.setdefault("quantized", {})["order"] = order
    path = os.path.join(tmp, f"scene_{order}.json")
    json.dump(s, open(path, "w"))
    return path


def cube(scene, arch, repeat, out_png, out_json, threads, judge, rss=None):
    cmd = [CUBE, "render", "--scene", scene, "--arch", arch, "--repeat", str(repeat),
           "--out", out_png, "--json", out_json]
    if judge:
        cmd.append("--compare-reference")
    run(cmd, env={"RAYON_NUM_THREADS": str(threads)}, rss=rss)
    return json.load(open(out_json))


def error_of(tmp, scene, png):
    j = os.path.join(tmp, os.path.basename(png) + ".error.json")
    run([CUBE, "compare", "--scene", scene, "--image", png, "--json", j])
    return json.load(open(j))["error"]


def fit_exponent(points):
    """Least-squares slope of log t on log n."""
    xs = [math.log(n) for n, _ in points]
    ys = [math.log(t) for _, t in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    sxx = sum((x - mx) ** 2 for x in xs)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sxx if sxx > 0 else None


def scene_rows(scene, cam, repeat, tmp):
    rows = []
    print(f"VolPack (classified shear-warp), {repeat} runs...", flush=True)
    png = os.path.join(tmp, "volpack.png")
    vp = volpack(scene, repeat, png)
    e = error_of(tmp, scene, png)
    rows.append({"renderer": "VolPack 1.0 (Debian libvolpack1-dev)", "method": "classified shear-warp",
                 "threads": 1, "frame_s": vp["frame_seconds"], "tf_change_s": vp["tf_change_seconds"],
                 "prep_s": vp["prep_seconds"], "error": e, "image": "volpack.png",
                 "notes": f"min voxel opacity {vp['min_voxel_opacity']}, max ray opacity "
                          f"{vp['max_ray_opacity']}; one material colour"})
    for threads in sorted({CORES, 1}, reverse=True):
        print(f"VTK (vtkFixedPointVolumeRayCastMapper), {threads} thread(s), {repeat} runs...", flush=True)
        png = os.path.join(tmp, f"vtk_{threads}t.png")
        vt = vtk(scene, cam, repeat, png, threads)
        rows.append({"renderer": f"VTK {vt['version']} (PyPI vtk)", "method": "vtkFixedPointVolumeRayCastMapper",
                     "threads": vt["threads"], "frame_s": vt["frame_seconds"],
                     "tf_change_s": vt["tf_change_seconds"], "prep_s": vt["prep_seconds"],
                     "error": error_of(tmp, scene, png), "image": f"vtk_{threads}t.png",
                     "notes": "sample distance 1 voxel, offscreen (EGL); prep = first render"})
    for name, arch, order in KIT:
        sc = kit_scene(scene, order, tmp)
        for threads in sorted({CORES, 1}, reverse=True):
            print(f"cube {name}, {threads} thread(s), {repeat} runs...", flush=True)
            png = os.path.join(tmp, f"{name}_{threads}t.png")
            j = cube(sc, arch, repeat, png, os.path.join(tmp, f"{name}_{threads}t.json"), threads, True)
            d = j.get("details", {})
            if arch.startswith("quantized"):
                tf, prep = d["tf_change_seconds"], d["volume_prep_seconds"]
                notes = f"n = {d['subdivisions']}, {d['normals']} normals, {d['order']}"
            else:
                # The golden models build their tables every frame: a
                # transfer-function change costs one frame. Per volume they
                # copy it into the view's traversal order, kept between
                # frames.
                tf, prep = d["frame_seconds"], d["volume_prep_seconds"]
                notes = "bit-exact fixed point, tables built every frame, traversal-order copy per volume"
            rows.append({"renderer": "cube", "method": name, "threads": threads,
                         "frame_s": d.get("frame_seconds", j["seconds"]), "tf_change_s": tf, "prep_s": prep,
                         "error": j["error"], "image": f"{name}_{threads}t.png", "notes": notes})
    return rows


PAIRS = 5
# Each kit renderer and the peer its goal names (issue: quantized
# projection against VolPack, the golden models against VTK).
PAIRED = [("quantized-projection", "VolPack"), ("quantized-projection-f2b", "VolPack"),
          ("cube4l", "VTK"), ("cube3", "VTK")]


def pairs(scene, cam, repeat, tmp):
    """PAIRS rounds of each peer, then each kit renderer measured against it."""
    png = os.path.join(tmp, "pair.png")
    ratios = {name: [] for name, _ in PAIRED}
    kit = {name: (arch, kit_scene(scene, order, tmp)) for name, arch, order in KIT}
    for k in range(PAIRS):
        print(f"pairs: round {k + 1} of {PAIRS}...", flush=True)
        for name, peer in PAIRED:
            arch, sc = kit[name]
            if peer == "VolPack":
                t_peer = volpack(scene, repeat, png)["frame_seconds"]
            else:
                t_peer = vtk(scene, cam, repeat, png, CORES)["frame_seconds"]
            j = cube(sc, arch, repeat, png, os.path.join(tmp, "pair.json"), CORES, False)
            ratios[name].append(j["details"].get("frame_seconds", j["seconds"]) / t_peer)
    out = []
    for name, peer in PAIRED:
        r = sorted(ratios[name])
        out.append({"renderer": name, "peer": peer,
                    "ratios": ratios[name], "median": r[len(r) // 2], "min": r[0], "max": r[-1]})
    return out


def scaling(template, sizes, repeat, tmp):
    s = json.load(open(template))
    table = []
    names = ["VolPack, 1 thread", f"VTK FixedPoint, {CORES} threads"] + [f"cube {k[0]}, {CORES} threads" for k in KIT]
    times = {n: {} for n in names}
    rss = {n: None for n in names}
    for n in sizes:
        d = os.path.join(tmp, f"phantom{n}")
        os.makedirs(d)
        s["volume"] = {"builtin": "phantom", "dims": [n, n, n]}
        built = os.path.join(d, "builtin.json")
        json.dump(s, open(built, "w"))
        run([CUBE, "volume", "--scene", built, "--out", os.path.join(d, "phantom.raw")])
        s["volume"] = {"raw": "phantom.raw", "dims": [n, n, n], "type": "u8"}
        scene = os.path.join(d, "scene.json")
        json.dump(s, open(scene, "w"))
        last = n == sizes[-1]
        print(f"scaling: phantom {n}³...", flush=True)
        mem = []
        times[names[0]][n] = volpack(scene, repeat, os.path.join(d, "volpack.png"), rss=mem)["frame_seconds"]
        cam = vtk_camera(scene, d)
        times[names[1]][n] = vtk(scene, cam, repeat, os.path.join(d, "vtk.png"), CORES, rss=mem)["frame_seconds"]
        for (kit, a, order), name in zip(KIT, names[2:]):
            sc = kit_scene(scene, order, d)
            j = cube(sc, a, repeat, os.path.join(d, f"{kit}.png"), os.path.join(d, f"{kit}.json"), CORES, False, rss=mem)
            times[name][n] = j.get("details", {}).get("frame_seconds", j["seconds"])
        if last:
            for name, kib in zip(names, mem):
                rss[name] = kib
        shutil.rmtree(d)
    for name in names:
        pts = [(n ** 3, times[name][n]) for n in sizes]
        table.append({"renderer": name, "frame_s": {str(n): times[name][n] for n in sizes},
                      "exponent": fit_exponent(pts) if len(pts) > 1 else None,
                      "peak_rss_mib_at_largest": rss[name] / 1024 if rss[name] else None})
    return table


def ms(x):
    return "—" if x is None else f"{x * 1e3:.1f}"


def scene_markdown(sc, report):
    """A scene's table and its interleaved pairs."""
    ratio = lambda a, b: "—" if a is None or b is None else f"{a / b:.2f}"
    rows = sc["rows"]
    vp = rows[0]
    vtk_by = {r["threads"]: r for r in rows if r["renderer"].startswith("VTK")}
    md = [f"## {sc['scene']}", "",
          "| renderer | method | threads | per frame ms | after a TF change ms | per-volume prep ms "
          "| rel. Euclidean % | PSNR dB | frame / VolPack | TF change / VolPack | frame / VTK | notes |",
          "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in rows:
        e = r["error"]
        v = vtk_by.get(r["threads"])
        md.append(f"| {r['renderer']} | {r['method']} | {r['threads']} | {ms(r['frame_s'])} | {ms(r['tf_change_s'])} "
                  f"| {ms(r['prep_s'])} | {e['rel_euclid_pct']:.2f} | {e['psnr_db']:.2f} "
                  f"| {ratio(r['frame_s'], vp['frame_s'])} | {ratio(r['tf_change_s'], vp['tf_change_s'])} "
                  f"| {ratio(r['frame_s'], v and v['frame_s'])} | {r['notes']} |")
    pr = sc["pairs"]
    md += ["", f"### Interleaved pairs: {len(pr[0]['ratios'])} rounds", "",
           "Each round runs the peer, then the kit's renderer, each for a median of "
           f"{report['repeat']} frames, at {report['cores']} threads (VolPack at 1); the ratio is "
           "the kit's frame over the peer's in that round.", "",
           "| renderer | against | median ratio | range | every round |", "|---|---|---|---|---|"]
    for r in pr:
        md.append(f"| {r['renderer']} | {r['peer']} | **{r['median']:.2f}** | {r['min']:.2f}–{r['max']:.2f} "
                  f"| {', '.join(f'{x:.2f}' for x in r['ratios'])} |")
    return md


def markdown(report):
    md = ["# Peers", "",
          f"{report['cpu']}, {report['cores']} cores; medians of {report['repeat']} runs; {report['date']}. "
          "Ratios are time over the peer's time in this run (below 1: faster than the peer); "
          "the VTK ratio is against VTK at the same number of threads. Images are in each scene's folder."]
    for sc in report["scenes"]:
        md += [""] + scene_markdown(sc, report)
    sc = report.get("scaling")
    if sc:
        sizes = list(sc[0]["frame_s"].keys())
        md += ["", f"## Scaling: the built-in phantom, {report['scaling_scene']}", "",
               "Per frame ms at N³ voxels; the exponent is the least-squares slope of log time on log voxels; "
               f"memory is the process's peak resident set at {sizes[-1]}³.", "",
               "| renderer | " + " | ".join(f"{n}³" for n in sizes) + " | exponent | peak MiB |",
               "|---|" + "---|" * (len(sizes) + 2)]
        for r in sc:
            x = r["exponent"]
            m = r["peak_rss_mib_at_largest"]
            md.append(f"| {r['renderer']} | " + " | ".join(ms(r["frame_s"][n]) for n in sizes)
                      + f" | {'—' if x is None else f'{x:.2f}'} | {'—' if m is None else f'{m:.0f}'} |")
    return "\n".join(md) + "\n"


def stem(scene):
    return os.path.splitext(os.path.basename(scene))[0]


def main(scenes, repeat, out, sizes, scaling_scene):
    if len({stem(s) for s in scenes}) != len(scenes):
        fail(f"scenes {scenes} must have distinct file names (each scene's images go in OUT/<name>/)")
    cpu = next((l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name")), "?")
    os.makedirs(out, exist_ok=True)
    tmp = tempfile.mkdtemp(prefix=".peers.", dir=out)
    try:
        report = {"repeat": repeat, "cpu": cpu, "cores": CORES,
                  "date": datetime.date.today().isoformat(), "scenes": []}
        for scene in scenes:
            d = os.path.join(tmp, stem(scene))
            os.makedirs(d)
            # The reference's camera, for VTK: the table and the pairs share it.
            cam = vtk_camera(scene, d)
            report["scenes"].append({"scene": scene, "images": stem(scene), "rows": scene_rows(scene, cam, repeat, d),
                                     "pairs": pairs(scene, cam, repeat, d)})
        if sizes:
            report["scaling_scene"] = scaling_scene
            report["scaling"] = scaling(scaling_scene, sizes, repeat, tmp)
        open(os.path.join(tmp, "peers.json"), "w").write(json.dumps(report, indent=2) + "\n")
        open(os.path.join(tmp, "peers.md"), "w").write(markdown(report))
        # Every output is complete in tmp before any is moved into OUT.
        for sc in report["scenes"]:
            os.makedirs(os.path.join(out, sc["images"]), exist_ok=True)
            for r in sc["rows"]:
                f = os.path.join(sc["images"], r["image"])
                os.replace(os.path.join(tmp, f), os.path.join(out, f))
        for f in ["peers.json", "peers.md"]:
            os.replace(os.path.join(tmp, f), os.path.join(out, f))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    print(open(os.path.join(out, "peers.md")).read())


if __name__ == "__main__":
    a = sys.argv[1:]
    if len(a) != 5:
        fail("run.py SCENE[,SCENE...] REPEAT OUT SIZES SCALING_SCENE")
    main([x for x in a[0].split(",") if x], int(a[1]), a[2], [int(n) for n in a[3].split(",") if n], a[4])
