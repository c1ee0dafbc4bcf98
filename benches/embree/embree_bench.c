/*
 * Embree on the mesh benchmark's own work: the reference that docs/measurements.md compares this
 * renderer's BVH with. An optional measuring tool: no build of the crate compiles it, no test runs it.
 *
 * It reads a file that `cargo bench --bench mesh -- --dump-rays DIR` writes (the mesh's triangles and the
 * benchmark's primary, incoherent and shadow rays; the format is in benches/mesh.rs), builds an Embree
 * scene of the triangles, and times, on one thread, what the Rust benchmark times:
 *   - the build (rtcCommitScene, default build quality),
 *   - rtcIntersect1 for each primary and each incoherent ray (closest hit),
 *   - rtcOccluded1 for each shadow ray (any hit, ending at the light),
 * each the median of RUNS runs, by the wall clock and by the CPU time the process used. It prints its
 * hit counts beside the ones the Rust BVH found for the same rays.
 *
 * What it needs: gcc, and Embree 4, which the Python wheel `embreex` bundles (a shared library; the wheel
 * has no headers, so the few declarations used are written out below, as Embree 4's rtcore.h has them):
 *
 *   pip download --no-deps embreex==4.4.0.post1 -d /tmp/embree
 *   unzip -q -d /tmp/embree /tmp/embree/embreex-*.whl
 *   LIB=/tmp/embree/embreex.libs
 *   gcc -O2 -o /tmp/embree_bench benches/embree/embree_bench.c \
 *       "$LIB"/libembree4-*.so.4 -Wl,-rpath,"$LIB" -lm
 *   cargo bench --bench mesh -- --dump-rays /tmp/rays
 *   /tmp/embree_bench /tmp/rays/teapot.rays /tmp/rays/teapot-100k.rays
 *
 * (from the repository's root; the benchmark creates DIR if needed).
 *
 * Options: `--runs N` (default 5). Embree picks its widest kernels the processor has (AVX-512 on the
 * machines of docs/measurements.md) and, as it asks, runs with denormals flushed to zero.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <xmmintrin.h>

/* --- The part of Embree 4's API used here (rtcore_device.h, rtcore_scene.h, rtcore_geometry.h, rtcore_ray.h). */
typedef struct RTCDeviceTy *RTCDevice;
typedef struct RTCSceneTy *RTCScene;
typedef struct RTCGeometryTy *RTCGeometry;
enum { RTC_DEVICE_PROPERTY_VERSION = 0 };
enum { RTC_GEOMETRY_TYPE_TRIANGLE = 0 };
enum { RTC_BUFFER_TYPE_INDEX = 0, RTC_BUFFER_TYPE_VERTEX = 1 };
enum { RTC_FORMAT_UINT3 = 0x5003, RTC_FORMAT_FLOAT3 = 0x9003 };
#define RTC_INVALID_GEOMETRY_ID ((unsigned)-1)

struct __attribute__((aligned(16))) RTCRay {
    float org_x, org_y, org_z, tnear;
    float dir_x, dir_y, dir_z, time;
    float tfar;
    unsigned mask, id, flags;
};
struct __attribute__((aligned(16))) RTCHit {
    float Ng_x, Ng_y, Ng_z, u, v;
    unsigned primID, geomID;
    /* instID[1] and instPrimID[1] (Embree 4 with instance arrays), and room to spare. */
    unsigned inst[4];
};
struct __attribute__((aligned(16))) RTCRayHit {
    struct RTCRay ray;
    struct RTCHit hit;
};

RTCDevice rtcNewDevice(const char *config);
int rtcGetDeviceError(RTCDevice device);
ptrdiff_t rtcGetDeviceProperty(RTCDevice device, int property);
void rtcReleaseDevice(RTCDevice device);
RTCScene rtcNewScene(RTCDevice device);
void rtcCommitScene(RTCScene scene);
void rtcReleaseScene(RTCScene scene);
RTCGeometry rtcNewGeometry(RTCDevice device, int type);
void *rtcSetNewGeometryBuffer(RTCGeometry geometry, int type, unsigned slot, int format, size_t byteStride,
                              size_t itemCount);
void rtcCommitGeometry(RTCGeometry geometry);
unsigned rtcAttachGeometry(RTCScene scene, RTCGeometry geometry);
void rtcReleaseGeometry(RTCGeometry geometry);
/* The last argument (RTCIntersectArguments*, RTCOccludedArguments*) may be NULL: the defaults. */
void rtcIntersect1(RTCScene scene, struct RTCRayHit *rayhit, void *args);
void rtcOccluded1(RTCScene scene, struct RTCRay *ray, void *args);

/* --- The benchmark's file. */

/* One set of rays: start, direction and largest ray parameter (7 floats each), and the Rust BVH's hit count. */
struct RaySet {
    uint32_t count, rust_hits;
    float *rays;
};

struct Work {
    uint32_t triangle_count;
    float *corners; /* 9 floats per triangle */
    struct RaySet sets[3];
};

static void fail(const char *what, const char *file) {
    fprintf(stderr, "embree_bench: %s: %s\n", file, what);
    exit(2);
}

static void read_exactly(FILE *f, void *to, size_t bytes, const char *file) {
    if (fread(to, 1, bytes, f) != bytes) fail("the file ends too early", file);
}

static float *read_floats(FILE *f, size_t n, const char *file) {
    float *values = malloc(n * sizeof(float));
    if (!values) fail("out of memory", file);
    read_exactly(f, values, n * sizeof(float), file);
    return values;
}

static struct Work read_work(const char *file) {
    FILE *f = fopen(file, "rb");
    if (!f) fail("cannot open it", file);
    char magic[8];
    read_exactly(f, magic, 8, file);
    if (memcmp(magic, "L6RAYS1", 8) != 0) fail("not a file of `cargo bench --bench mesh -- --dump-rays`", file);
    struct Work w;
    read_exactly(f, &w.triangle_count, 4, file);
    w.corners = read_floats(f, 9 * (size_t)w.triangle_count, file);
    for (int s = 0; s < 3; s++) {
        read_exactly(f, &w.sets[s].count, 4, file);
        read_exactly(f, &w.sets[s].rust_hits, 4, file);
        w.sets[s].rays = read_floats(f, 7 * (size_t)w.sets[s].count, file);
    }
    fclose(f);
    return w;
}

/* --- Timing: the wall clock, and the CPU time of the whole process (Embree runs on this thread alone). */

struct Times {
    double wall, cpu;
};

static double seconds(clockid_t clock) {
    struct timespec t;
    clock_gettime(clock, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static struct Times now(void) {
    return (struct Times){seconds(CLOCK_MONOTONIC), seconds(CLOCK_PROCESS_CPUTIME_ID)};
}

static int by_value(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The median of n values (the upper one of the middle two, as the Rust benchmark takes it). */
static double median(double *values, int n) {
    qsort(values, n, sizeof(double), by_value);
    return values[n / 2];
}

/* --- Embree. */

static RTCScene build_scene(RTCDevice device, const struct Work *w) {
    RTCScene scene = rtcNewScene(device);
    RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
    size_t n = w->triangle_count;
    float *vertices =
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * n);
    unsigned *indices =
        rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), n);
    memcpy(vertices, w->corners, 9 * n * sizeof(float));
    for (unsigned i = 0; i < 3 * n; i++) indices[i] = i;
    rtcCommitGeometry(geometry);
    rtcAttachGeometry(scene, geometry);
    rtcReleaseGeometry(geometry);
    rtcCommitScene(scene);
    return scene;
}

static struct RTCRay make_ray(const float *r) {
    return (struct RTCRay){
        .org_x = r[0], .org_y = r[1], .org_z = r[2], .tnear = 0.0f,
        .dir_x = r[3], .dir_y = r[4], .dir_z = r[5], .time = 0.0f,
        .tfar = r[6], .mask = ~0u, .id = 0, .flags = 0,
    };
}

/* Traces every ray of the set once: closest hits, or (`any`) occlusion. Returns how many hit. */
static uint32_t trace(RTCScene scene, const struct RaySet *set, int any) {
    uint32_t hits = 0;
    for (uint32_t i = 0; i < set->count; i++) {
        const float *r = set->rays + 7 * (size_t)i;
        if (any) {
            struct RTCRay ray = make_ray(r);
            rtcOccluded1(scene, &ray, NULL);
            hits += ray.tfar < 0.0f; /* Embree sets tfar to -inf when something is in the way */
        } else {
            struct RTCRayHit rh = {.ray = make_ray(r)};
            rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
            rtcIntersect1(scene, &rh, NULL);
            hits += rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
        }
    }
    return hits;
}

int main(int argc, char **argv) {
    int runs = 5;
    /* Embree asks for denormals flushed to zero (flush to zero and denormals are zero, MXCSR bits 15 and 6). */
    _mm_setcsr(_mm_getcsr() | 0x8040);
    RTCDevice device = rtcNewDevice("threads=1");
    if (!device || rtcGetDeviceError(device) != 0) fail("cannot create an Embree device", "threads=1");
    long version = (long)rtcGetDeviceProperty(device, RTC_DEVICE_PROPERTY_VERSION);
    printf("Embree %ld.%ld.%ld, one thread\n", version / 10000, version / 100 % 100, version % 100);
    for (int a = 1; a < argc; a++) {
        if (strcmp(argv[a], "--runs") == 0 && a + 1 < argc) {
            runs = atoi(argv[++a]);
            if (runs < 1) runs = 1;
            continue;
        }
        struct Work w = read_work(argv[a]);
        double wall[runs], cpu[runs];
        for (int k = 0; k < runs; k++) {
            struct Times t0 = now();
            RTCScene scene = build_scene(device, &w);
            struct Times t1 = now();
            rtcReleaseScene(scene);
            wall[k] = t1.wall - t0.wall;
            cpu[k] = t1.cpu - t0.cpu;
        }
        printf("%s: %u triangles, built in %.2f ms (CPU time: %.2f ms)\n", argv[a], w.triangle_count,
               1e3 * median(wall, runs), 1e3 * median(cpu, runs));
        RTCScene scene = build_scene(device, &w);
        static const char *names[3] = {"primary   ", "incoherent", "shadow    "};
        for (int s = 0; s < 3; s++) {
            const struct RaySet *set = &w.sets[s];
            uint32_t hits = 0;
            for (int k = 0; k < runs; k++) {
                struct Times t0 = now();
                hits = trace(scene, set, s == 2);
                struct Times t1 = now();
                wall[k] = t1.wall - t0.wall;
                cpu[k] = t1.cpu - t0.cpu;
            }
            double mrays = set->count * 1e-6;
            printf("  1 thread(s): %s %6.2f Mrays/s (CPU time: %6.2f), %u of %u %s (the Rust BVH: %u)\n", names[s],
                   mrays / median(wall, runs), mrays / median(cpu, runs), hits, set->count,
                   s == 2 ? "occluded" : "hit", set->rust_hits);
        }
        rtcReleaseScene(scene);
        free(w.corners);
        for (int s = 0; s < 3; s++) free(w.sets[s].rays);
    }
    rtcReleaseDevice(device);
    return 0;
}
