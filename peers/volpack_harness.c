/*
 * VolPack's classified shear-warp on a cube scene, for scripts/peers.
 *
 * Usage: volpack_harness RAW NX NY NZ RX RY RZ HALFWIDTH W H REPEAT OUT.ppm
 *                        AMBIENT DIFFUSE SPECULAR SHININESS LX LY LZ R G B
 *                        N X0 A0 X1 A1 ...   (opacity ramp, intensities 0..255)
 *
 * The volume is u8, x fastest. Rotations are applied x first, then y, then
 * z (VP_CONCAT_LEFT), as the scene's `rotate_deg`. HALFWIDTH is the
 * orthographic window's half width in VolPack's object units (the largest
 * dimension has length 1). Shading is one material with the colour R G B
 * (VolPack's lookup shader indexes by normal only). Timings go to stdout as
 * one JSON line: the medians over REPEAT runs of
 *   prep:      vpVolumeNormals + vpClassifyVolume (once per volume),
 *   frame:     vpShadeTable + vpRenderClassifiedVolume at the view,
 *   tf_change: vpClassifyVolume with the opacity table set again + frame.
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <volpack.h>

typedef struct {
    short normal;
    unsigned char density;
    unsigned char gradient;
} Voxel;

static double now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + t.tv_nsec * 1e-9;
}

static int cmp(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static double median(double *v, int n) {
    qsort(v, n, sizeof *v, cmp);
    return v[n / 2];
}

static void check(vpContext *vpc, vpResult r, const char *what) {
    if (r != VP_OK) {
        fprintf(stderr, "volpack_harness: %s: %s\n", what, vpGetErrorString(vpGetError(vpc)));
        exit(1);
    }
}

int main(int argc, char **argv) {
    if (argc < 24) {
        fprintf(stderr, "volpack_harness: too few arguments (see the source)\n");
        return 1;
    }
    const char *raw = argv[1];
    int nx = atoi(argv[2]), ny = atoi(argv[3]), nz = atoi(argv[4]);
    double rx = atof(argv[5]), ry = atof(argv[6]), rz = atof(argv[7]), half = atof(argv[8]);
    int w = atoi(argv[9]), h = atoi(argv[10]), repeat = atoi(argv[11]);
    const char *out = argv[12];
    double amb = atof(argv[13]), dif = atof(argv[14]), spe = atof(argv[15]), shi = atof(argv[16]);
    double lx = atof(argv[17]), ly = atof(argv[18]), lz = atof(argv[19]);
    double cr = atof(argv[20]), cg = atof(argv[21]), cb = atof(argv[22]);
    int np = atoi(argv[23]);
    if (argc != 24 + 2 * np || np < 2 || np > 64 || repeat < 1) {
        fprintf(stderr, "volpack_harness: bad opacity ramp or repeat\n");
        return 1;
    }
    int rampx[64];
    float rampy[64];
    for (int i = 0; i < np; i++) {
        rampx[i] = atoi(argv[24 + 2 * i]);
        rampy[i] = (float)atof(argv[25 + 2 * i]);
    }
    size_t n = (size_t)nx * ny * nz;
    unsigned char *density = malloc(n);
    FILE *f = fopen(raw, "rb");
    if (!f || fread(density, 1, n, f) != n) {
        fprintf(stderr, "volpack_harness: reading %s\n", raw);
        return 1;
    }
    fclose(f);
    Voxel *vol = malloc(n * sizeof(Voxel));
    Voxel *dummy = NULL;
    vpContext *vpc = vpCreateContext();
    vpSetVolumeSize(vpc, nx, ny, nz);
    vpSetVoxelSize(vpc, sizeof(Voxel), 3, 1, 1);
    vpSetVoxelField(vpc, 0, sizeof(short), vpFieldOffset(dummy, normal), VP_NORM_MAX);
    vpSetVoxelField(vpc, 1, 1, vpFieldOffset(dummy, density), 255);
    vpSetVoxelField(vpc, 2, 1, vpFieldOffset(dummy, gradient), VP_GRAD_MAX);
    vpSetRawVoxels(vpc, vol, n * sizeof(Voxel), sizeof(Voxel), nx * sizeof(Voxel), nx * ny * sizeof(Voxel));
    float opacity[256];
    vpRamp(opacity, sizeof(float), np, rampx, rampy);
    check(vpc, vpSetClassifierTable(vpc, 0, 1, opacity, sizeof(opacity)), "vpSetClassifierTable");

    static float shade_table[VP_NORM_MAX + 1][3];
    check(vpc, vpSetLookupShader(vpc, 3, 1, 0, &shade_table[0][0], sizeof(shade_table), 0, NULL, 0), "vpSetLookupShader");
    vpSetMaterial(vpc, VP_MATERIAL0, VP_AMBIENT, VP_BOTH_SIDES, amb * cr, amb * cg, amb * cb);
    vpSetMaterial(vpc, VP_MATERIAL0, VP_DIFFUSE, VP_BOTH_SIDES, dif * cr, dif * cg, dif * cb);
    vpSetMaterial(vpc, VP_MATERIAL0, VP_SPECULAR, VP_BOTH_SIDES, spe, spe, spe);
    vpSetMaterial(vpc, VP_MATERIAL0, VP_SHINYNESS, VP_BOTH_SIDES, shi, 0.0, 0.0);
    vpSetLight(vpc, VP_LIGHT0, VP_DIRECTION, lx, ly, lz);
    vpSetLight(vpc, VP_LIGHT0, VP_COLOR, 1.0, 1.0, 1.0);
    vpEnable(vpc, VP_LIGHT0, 1);

    vpCurrentMatrix(vpc, VP_MODEL);
    vpIdentityMatrix(vpc);
    vpSeti(vpc, VP_CONCAT_MODE, VP_CONCAT_LEFT);
    vpRotate(vpc, VP_X_AXIS, rx);
    vpRotate(vpc, VP_Y_AXIS, ry);
    vpRotate(vpc, VP_Z_AXIS, rz);
    vpCurrentMatrix(vpc, VP_PROJECT);
    vpIdentityMatrix(vpc);
    vpWindow(vpc, VP_PARALLEL, -half, half, -half * h / w, half * h / w, -half, half);
    vpCurrentMatrix(vpc, VP_MODEL);
    unsigned char *image = malloc((size_t)w * h * 3);
    vpSetImage(vpc, image, w, h, w * 3, VP_RGB);

    double *prep = malloc(repeat * sizeof(double)), *frame = malloc(repeat * sizeof(double)),
           *tf = malloc(repeat * sizeof(double));
    for (int k = 0; k < repeat; k++) {
        double t = now();
        check(vpc, vpVolumeNormals(vpc, density, n, 1, 2, 0), "vpVolumeNormals");
        check(vpc, vpClassifyVolume(vpc), "vpClassifyVolume");
        prep[k] = now() - t;
    }
    for (int k = 0; k < repeat; k++) {
        double t = now();
        check(vpc, vpShadeTable(vpc), "vpShadeTable");
        check(vpc, vpRenderClassifiedVolume(vpc), "vpRenderClassifiedVolume");
        frame[k] = now() - t;
    }
    for (int k = 0; k < repeat; k++) {
        double t = now();
        vpRamp(opacity, sizeof(float), np, rampx, rampy);
        check(vpc, vpSetClassifierTable(vpc, 0, 1, opacity, sizeof(opacity)), "vpSetClassifierTable");
        check(vpc, vpClassifyVolume(vpc), "vpClassifyVolume");
        check(vpc, vpShadeTable(vpc), "vpShadeTable");
        check(vpc, vpRenderClassifiedVolume(vpc), "vpRenderClassifiedVolume");
        tf[k] = now() - t;
    }
    /* VolPack's image has its first row at the bottom: write it top first. */
    FILE *o = fopen(out, "wb");
    if (!o) {
        fprintf(stderr, "volpack_harness: writing %s\n", out);
        return 1;
    }
    fprintf(o, "P6\n%d %d\n255\n", w, h);
    for (int y = h - 1; y >= 0; y--)
        fwrite(image + (size_t)y * w * 3, 1, (size_t)w * 3, o);
    fclose(o);
    double minop, maxray;
    vpGetd(vpc, VP_MIN_VOXEL_OPACITY, &minop);
    vpGetd(vpc, VP_MAX_RAY_OPACITY, &maxray);
    printf("{\"prep_seconds\": %g, \"frame_seconds\": %g, \"tf_change_seconds\": %g, \"min_voxel_opacity\": %g, \"max_ray_opacity\": %g}\n",
           median(prep, repeat), median(frame, repeat), median(tf, repeat), minop, maxray);
    return 0;
}
