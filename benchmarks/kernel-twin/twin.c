// The library's closest-hit kernel, written again in C: the traversal of ClosestHitTraversal.intersect, the eight-box
// test of VectorWideBoxTest, the leaf filter of VectorLeafFilter and the watertight test of WatertightTriangle, with
// the same operations in the same order (so the same bits), over the nodes, triangles, records and rays that
// src/test/java/geometries/KernelTwinExport.java wrote. It checks every distance against the library's and prints
// M rays per CPU-second. Diagnostic only (docs/BENCHMARKS.md, "27 Nov, 14:00-14:40 UTC: the kernel's C twin"):
// beside the library's figure it separates what the algorithm and its data cost from what the JIT's code costs.
// Linux, x86-64 with AVX2 and FMA:
//   gcc -O2 -mavx2 -mfma -ffp-contract=off -o twin twin.c -lm && ./twin DIR [passes [prefetch]]
// "prefetch" alternates the passes with a variant that prefetches as Embree does (docs/BENCHMARKS.md, "27 Nov,
// 15:30-15:55 UTC").
// -ffp-contract=off keeps gcc from fusing products and sums that Java rounds apart.
#include <immintrin.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <time.h>

// The layout, as BVH and CompiledPrimitives define it; checked against the header the export writes.
enum {
    WIDTH = 8, NODE_STRIDE = 64, FIRST_NODE = 12, MIN_X = 0, MIN_Y = 8, MIN_Z = 16, MAX_X = 24, MAX_Y = 32,
    MAX_Z = 40, LINK = 48, COUNT = 56, INFO = 4, INDEX = 0, EDGES = 1, FILLED = 8,
    STACK_SIZE = (WIDTH - 1) * 64 + 2
};
static const int LAYOUT[] = {WIDTH, NODE_STRIDE, FIRST_NODE, MIN_X, MAX_X, LINK, COUNT, INFO, INDEX, EDGES, FILLED};
enum { LAYOUT_INTS = sizeof LAYOUT / sizeof LAYOUT[0] };

static float *nodes;
static double *triangles;
static int32_t *info;
static int rootLink, rootCount;
// A probe the library cannot make: Java has no prefetch instruction (`twin DIR passes prefetch`).
static int prefetching;

// A ray with the constants Ray derives: reciprocals, the watertight test's axes and shear.
typedef struct {
    double ox, oy, oz, dx, dy, dz, ix, iy, iz, sx, sy, sz;
    int kx, ky, kz;
} Ray;

typedef struct {
    double t, u, v;
    int owner, part;
    long nodeVisits, primitiveTests;
} Hit;

// Reads a file whole into memory on huge pages where the kernel grants them (as Embree's BVH and the benchmark's
// heap are), with room past its end for the four-lane loads of a last leaf.
static void *load(const char *dir, const char *name, size_t *bytes) {
    char path[1024];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    FILE *f = fopen(path, "rb");
    if (!f) {
        perror(path);
        exit(1);
    }
    fseek(f, 0, SEEK_END);
    size_t n = ftell(f);
    fseek(f, 0, SEEK_SET);
    size_t size = (n + 256 + (1 << 21) - 1) / (1 << 21) * (1 << 21);
    void *p = aligned_alloc(1 << 21, size);
    madvise(p, size, MADV_HUGEPAGE);
    memset(p, 0, size);
    if (fread(p, 1, n, f) != n) {
        perror(path);
        exit(1);
    }
    fclose(f);
    if (bytes) *bytes = n;
    return p;
}

// Java's Math.nextUp, for the finite or +inf values used here (a libm call costs the twin a fifth of its speed).
static inline float nextUpF(float f) {
    if (f == INFINITY) return f;
    if (f == 0) return 0x1p-149f;
    int32_t b;
    memcpy(&b, &f, 4);
    b += b >= 0 ? 1 : -1;
    memcpy(&f, &b, 4);
    return f;
}

static inline float nextDownF(float f) { return -nextUpF(-f); }

static inline double nextUpD(double d) {
    if (d == INFINITY) return d;
    if (d == 0) return 0x1p-1074;
    int64_t b;
    memcpy(&b, &d, 8);
    b += b >= 0 ? 1 : -1;
    memcpy(&d, &b, 8);
    return d;
}

static inline double minD(double a, double b) { return a < b ? a : b; }
static inline double maxD(double a, double b) { return a > b ? a : b; }

// Util.differenceOfProducts.
static inline double dop(double a, double b, double c, double d) {
    double cd = c * d;
    return fma(a, b, -cd) + fma(-c, d, cd);
}

static inline double direction(const Ray *r, int axis) { return axis == 0 ? r->dx : axis == 1 ? r->dy : r->dz; }
static inline double origin(const Ray *r, int axis) { return axis == 0 ? r->ox : axis == 1 ? r->oy : r->oz; }

// Ray.derive.
static void derive(Ray *r) {
    r->ix = 1.0 / r->dx;
    r->iy = 1.0 / r->dy;
    r->iz = 1.0 / r->dz;
    double ax = fabs(r->dx), ay = fabs(r->dy), az = fabs(r->dz);
    int k = ax > ay ? (ax > az ? 0 : 2) : (ay > az ? 1 : 2);
    r->kz = k;
    r->kx = k == 2 ? 0 : k + 1;
    r->ky = r->kx == 2 ? 0 : r->kx + 1;
    r->sz = k == 0 ? r->ix : k == 1 ? r->iy : r->iz;
    r->sx = -direction(r, r->kx) * r->sz;
    r->sy = -direction(r, r->ky) * r->sz;
}

#define GAMMA(n) (((n) * 0x1p-53) / (1 - (n) * 0x1p-53))

static int owns(int shared, int edge, double dx, double dy, double orientation) {
    if ((shared & edge) == 0) return 0;
    double ody = orientation * dy;
    return ody > 0 || (ody == 0 && orientation * dx > 0);
}

// WatertightTriangle.intersect with a stride; a call, as in the library.
static int __attribute__((noinline)) watertight(const double *v, int a, int b, int c, int stride, int shared,
        const Ray *ray, double tMin, double tMax, Hit *hit) {
    int kx = ray->kx * stride, ky = ray->ky * stride, kz = ray->kz * stride;
    double ox = origin(ray, ray->kx), oy = origin(ray, ray->ky), oz = origin(ray, ray->kz);
    double p0x = v[a + kx] - ox, p0y = v[a + ky] - oy, p0z = v[a + kz] - oz;
    double p1x = v[b + kx] - ox, p1y = v[b + ky] - oy, p1z = v[b + kz] - oz;
    double p2x = v[c + kx] - ox, p2y = v[c + ky] - oy, p2z = v[c + kz] - oz;
    double sx = ray->sx, sy = ray->sy;
    p0x += sx * p0z;
    p0y += sy * p0z;
    p1x += sx * p1z;
    p1y += sy * p1z;
    p2x += sx * p2z;
    p2y += sy * p2z;
    double e0 = dop(p1x, p2y, p1y, p2x), e1 = dop(p2x, p0y, p2y, p0x), e2 = dop(p0x, p1y, p0y, p1x);
    double lowest = minD(e0, minD(e1, e2)), highest = maxD(e0, maxD(e1, e2));
    if ((lowest < 0) & (highest > 0)) return 0;
    double det = e0 + e1 + e2;
    if (det == 0) return 0;
    if (e0 == 0 || e1 == 0 || e2 == 0) {
        double orientation = det > 0 ? 1 : -1;
        if (e0 == 0 && !owns(shared, 1, p2x - p1x, p2y - p1y, orientation)) return 0;
        if (e1 == 0 && !owns(shared, 2, p0x - p2x, p0y - p2y, orientation)) return 0;
        if (e2 == 0 && !owns(shared, 4, p1x - p0x, p1y - p0y, orientation)) return 0;
    }
    double sz = ray->sz;
    p0z *= sz;
    p1z *= sz;
    p2z *= sz;
    double tScaled = e0 * p0z + e1 * p1z + e2 * p2z;
    if (det < 0 ? (tScaled >= 0 || tScaled < tMax * det) : (tScaled <= 0 || tScaled > tMax * det)) return 0;
    double invDet = 1 / det;
    double t = tScaled * invDet;
    if (!(t < tMax) || !(t > tMin)) return 0;
    double maxZt = maxD(fabs(p0z), maxD(fabs(p1z), fabs(p2z)));
    double deltaZ = GAMMA(3) * maxZt;
    double maxXt = maxD(fabs(p0x), maxD(fabs(p1x), fabs(p2x)));
    double maxYt = maxD(fabs(p0y), maxD(fabs(p1y), fabs(p2y)));
    double deltaX = GAMMA(5) * (maxXt + maxZt);
    double deltaY = GAMMA(5) * (maxYt + maxZt);
    double deltaE = 2 * (GAMMA(2) * maxXt * maxYt + deltaY * maxXt + deltaX * maxYt);
    double maxE = maxD(fabs(e0), maxD(fabs(e1), fabs(e2)));
    double deltaT = 3 * (GAMMA(3) * maxE * maxZt + deltaE * maxZt + deltaZ * maxE) * fabs(invDet);
    if (t <= deltaT) return 0;
    hit->t = t;
    hit->u = e1 * invDet;
    hit->v = e2 * invDet;
    return 1;
}

// RaySlabs: the float reciprocals and the origin offsets rounded outward, broadcast once per ray.
typedef struct {
    __m256 invX, invY, invZ, nearX, nearY, nearZ, farX, farY, farZ;
    int flipX, flipY, flipZ;
} Slabs;

static inline void setSlabs(Slabs *s, const Ray *r) {
    s->flipX = (r->ix < 0) * MAX_X;
    s->flipY = (r->iy < 0) * MAX_X;
    s->flipZ = (r->iz < 0) * MAX_X;
    double ox = r->ox * r->ix, oy = r->oy * r->iy, oz = r->oz * r->iz;
    double sx = fabs(ox) * 0x1p-21 + 0x1p-140, sy = fabs(oy) * 0x1p-21 + 0x1p-140, sz = fabs(oz) * 0x1p-21 + 0x1p-140;
    s->invX = _mm256_set1_ps((float)r->ix);
    s->invY = _mm256_set1_ps((float)r->iy);
    s->invZ = _mm256_set1_ps((float)r->iz);
    // Negated: the box test adds them, as the Vector API's fma(bound, inv, -offset) does.
    s->nearX = _mm256_set1_ps(-(float)(ox + sx));
    s->nearY = _mm256_set1_ps(-(float)(oy + sy));
    s->nearZ = _mm256_set1_ps(-(float)(oz + sz));
    s->farX = _mm256_set1_ps(-(float)(ox - sx));
    s->farY = _mm256_set1_ps(-(float)(oy - sy));
    s->farZ = _mm256_set1_ps(-(float)(oz - sz));
}

// VectorWideBoxTest.test: the eight child boxes of the node at n; the hit mask, entry distances in entries.
static inline int boxTest(const float *n, const Slabs *s, float tMin, float tMax, float *entries) {
    __m256 nx = _mm256_fmadd_ps(_mm256_load_ps(n + MIN_X + s->flipX), s->invX, s->nearX);
    __m256 ny = _mm256_fmadd_ps(_mm256_load_ps(n + MIN_Y + s->flipY), s->invY, s->nearY);
    __m256 nz = _mm256_fmadd_ps(_mm256_load_ps(n + MIN_Z + s->flipZ), s->invZ, s->nearZ);
    __m256 fx = _mm256_fmadd_ps(_mm256_load_ps(n + MAX_X - s->flipX), s->invX, s->farX);
    __m256 fy = _mm256_fmadd_ps(_mm256_load_ps(n + MAX_Y - s->flipY), s->invY, s->farY);
    __m256 fz = _mm256_fmadd_ps(_mm256_load_ps(n + MAX_Z - s->flipZ), s->invZ, s->farZ);
    __m256 near = _mm256_blendv_ps(nx, ny, _mm256_cmp_ps(nx, ny, _CMP_LT_OQ));
    near = _mm256_blendv_ps(near, nz, _mm256_cmp_ps(near, nz, _CMP_LT_OQ));
    __m256 far = _mm256_blendv_ps(fx, fy, _mm256_cmp_ps(fy, fx, _CMP_LT_OQ));
    far = _mm256_blendv_ps(far, fz, _mm256_cmp_ps(fz, far, _CMP_LT_OQ));
    const __m256 magnitude = _mm256_castsi256_ps(_mm256_set1_epi32(0x7fffffff));
    near = _mm256_fmadd_ps(_mm256_and_ps(near, magnitude), _mm256_set1_ps(-0x1p-21f), near);
    far = _mm256_fmadd_ps(_mm256_and_ps(far, magnitude), _mm256_set1_ps(0x1p-21f), far);
    __m256 hit = _mm256_and_ps(_mm256_cmp_ps(near, far, _CMP_LE_OQ),
            _mm256_and_ps(_mm256_cmp_ps(near, _mm256_set1_ps(tMax), _CMP_LE_OQ),
                    _mm256_cmp_ps(far, _mm256_set1_ps(tMin), _CMP_GE_OQ)));
    _mm256_storeu_ps(entries, _mm256_blendv_ps(_mm256_set1_ps(INFINITY), near, hit));
    return _mm256_movemask_ps(hit);
}

// VectorLeafFilter.candidates: the lanes whose edge functions have one sign and whose determinant is not zero.
static int __attribute__((noinline)) leafFilter(const double *lanes, int o, int count, const Ray *r) {
    int kx = count * r->kx, ky = count * r->ky, kz = count * r->kz;
    __m256d ox = _mm256_set1_pd(origin(r, r->kx)), oy = _mm256_set1_pd(origin(r, r->ky));
    __m256d oz = _mm256_set1_pd(origin(r, r->kz));
    __m256d sx = _mm256_set1_pd(r->sx), sy = _mm256_set1_pd(r->sy);
    int v1 = o + 3 * count, v2 = o + 6 * count;
    __m256d p0z = _mm256_sub_pd(_mm256_loadu_pd(lanes + o + kz), oz);
    __m256d p1z = _mm256_sub_pd(_mm256_loadu_pd(lanes + v1 + kz), oz);
    __m256d p2z = _mm256_sub_pd(_mm256_loadu_pd(lanes + v2 + kz), oz);
    __m256d p0x = _mm256_add_pd(_mm256_sub_pd(_mm256_loadu_pd(lanes + o + kx), ox), _mm256_mul_pd(p0z, sx));
    __m256d p0y = _mm256_add_pd(_mm256_sub_pd(_mm256_loadu_pd(lanes + o + ky), oy), _mm256_mul_pd(p0z, sy));
    __m256d p1x = _mm256_add_pd(_mm256_sub_pd(_mm256_loadu_pd(lanes + v1 + kx), ox), _mm256_mul_pd(p1z, sx));
    __m256d p1y = _mm256_add_pd(_mm256_sub_pd(_mm256_loadu_pd(lanes + v1 + ky), oy), _mm256_mul_pd(p1z, sy));
    __m256d p2x = _mm256_add_pd(_mm256_sub_pd(_mm256_loadu_pd(lanes + v2 + kx), ox), _mm256_mul_pd(p2z, sx));
    __m256d p2y = _mm256_add_pd(_mm256_sub_pd(_mm256_loadu_pd(lanes + v2 + ky), oy), _mm256_mul_pd(p2z, sy));
    __m256d c0 = _mm256_mul_pd(p1y, p2x), c1 = _mm256_mul_pd(p2y, p0x), c2 = _mm256_mul_pd(p0y, p1x);
    __m256d e0 = _mm256_add_pd(_mm256_fmsub_pd(p1x, p2y, c0), _mm256_fnmadd_pd(p1y, p2x, c0));
    __m256d e1 = _mm256_add_pd(_mm256_fmsub_pd(p2x, p0y, c1), _mm256_fnmadd_pd(p2y, p0x, c1));
    __m256d e2 = _mm256_add_pd(_mm256_fmsub_pd(p0x, p1y, c2), _mm256_fnmadd_pd(p0y, p1x, c2));
    __m256d lowest = _mm256_min_pd(_mm256_min_pd(e0, e1), e2), highest = _mm256_max_pd(_mm256_max_pd(e0, e1), e2);
    __m256d zero = _mm256_setzero_pd();
    __m256d outside = _mm256_or_pd(
            _mm256_and_pd(_mm256_cmp_pd(lowest, zero, _CMP_LT_OQ), _mm256_cmp_pd(highest, zero, _CMP_GT_OQ)),
            _mm256_cmp_pd(_mm256_add_pd(_mm256_add_pd(e0, e1), e2), zero, _CMP_EQ_OQ));
    return ~_mm256_movemask_pd(outside) & 0xF;
}

static inline int nodeInt(int at) {
    int32_t value;
    memcpy(&value, nodes + at, 4);
    return value;
}

// As Embree's traversal does (BVH::prefetch): every hit child's lines requested as soon as the mask is known, so that
// the misses of the children postponed overlap with the work on the nearest. Always inlined: as a call, gcc finds it
// free of side effects (prefetches do not count) and drops it.
static inline __attribute__((always_inline)) void prefetchChildren(int o, int mask) {
    for (; mask; mask &= mask - 1) {
        int c = __builtin_ctz(mask), link = nodeInt(o + LINK + c), count = nodeInt(o + COUNT + c);
        if (count == 0) {
            const char *p = (const char *)(nodes + FIRST_NODE + NODE_STRIDE * link);
            __builtin_prefetch(p);
            __builtin_prefetch(p + 64);
            __builtin_prefetch(p + 128);
            __builtin_prefetch(p + 192);
        } else { // a leaf's lanes (288 bytes when full) and its first record
            const char *p = (const char *)(triangles + 9 * link);
            __builtin_prefetch(p);
            __builtin_prefetch(p + 64);
            __builtin_prefetch(p + 128);
            __builtin_prefetch(p + 192);
            __builtin_prefetch(p + 256);
            __builtin_prefetch(info + INFO * link);
        }
    }
}

// ClosestHitTraversal.intersect over the tree: nearest child first, farther ones postponed on the stack.
static int intersect(const Ray *ray, double tMin, double tMax, Hit *hit) {
    static int stack[2 * STACK_SIZE];
    static double stackEntry[STACK_SIZE];
    static float entries[WIDTH] __attribute__((aligned(32)));
    int best = INT32_MAX, bestTriangle = -1;
    double tieLimit = tMax;
    long visits = 1, tests = 0; // counted as the library counts them
    Slabs s;
    setSlabs(&s, ray);
    float tMinF = nextDownF((float)tMin), tMaxF = nextUpF((float)tMax);
    int sp = 0, link = rootLink, count = rootCount, more = 1;
    while (more) {
        if (count > 0) {
            tests += count;
            int filled = info[INFO * link + EDGES] >= FILLED;
            int candidates = !filled ? (1 << count) - 1
                    : count > 1      ? leafFilter(triangles, 9 * link, count, ray) & ((1 << count) - 1)
                                     : 1;
            for (; candidates; candidates &= candidates - 1) {
                int i = __builtin_ctz(candidates), k = link + i, index = info[INFO * k + INDEX];
                int a = filled ? 9 * link + i : 9 * k, stride = filled ? count : 1;
                if (watertight(triangles, a, a + 3 * stride, a + 6 * stride, stride, info[INFO * k + EDGES] & 7, ray,
                            tMin, index < best ? tieLimit : tMax, hit)) {
                    tMax = hit->t;
                    tMaxF = nextUpF((float)tMax);
                    tieLimit = nextUpD(tMax);
                    best = index;
                    bestTriangle = k;
                }
            }
        } else {
            int o = FIRST_NODE + NODE_STRIDE * link;
            visits += WIDTH;
            int mask = boxTest(nodes + o, &s, tMinF, tMaxF, entries);
            if (prefetching) prefetchChildren(o, mask);
            if (mask) {
                int rest = mask & (mask - 1);
                if (!rest) {
                    int only = __builtin_ctz(mask);
                    link = nodeInt(o + LINK + only);
                    count = nodeInt(o + COUNT + only);
                    continue;
                }
                if (!(rest & (rest - 1))) {
                    int a = __builtin_ctz(mask), b = __builtin_ctz(rest), far = a, near = b;
                    float farEntry = entries[a];
                    if (entries[a] < entries[b]) {
                        far = b;
                        near = a;
                        farEntry = entries[b];
                    }
                    stack[2 * sp] = nodeInt(o + LINK + far);
                    stack[2 * sp + 1] = nodeInt(o + COUNT + far);
                    stackEntry[sp++] = farEntry;
                    link = nodeInt(o + LINK + near);
                    count = nodeInt(o + COUNT + near);
                    continue;
                }
                int base = sp;
                for (; mask; mask &= mask - 1) {
                    int c = __builtin_ctz(mask), j = sp++;
                    float e = entries[c];
                    for (; j > base && stackEntry[j - 1] < e; j--) {
                        stack[2 * j] = stack[2 * j - 2];
                        stack[2 * j + 1] = stack[2 * j - 1];
                        stackEntry[j] = stackEntry[j - 1];
                    }
                    stack[2 * j] = nodeInt(o + LINK + c);
                    stack[2 * j + 1] = nodeInt(o + COUNT + c);
                    stackEntry[j] = e;
                }
                sp--;
                link = stack[2 * sp];
                count = stack[2 * sp + 1];
                continue;
            }
        }
        more = 0;
        while (sp > 0) {
            if (stackEntry[--sp] <= tMax) {
                link = stack[2 * sp];
                count = stack[2 * sp + 1];
                more = 1;
                break;
            }
        }
    }
    hit->nodeVisits += visits;
    hit->primitiveTests += tests;
    if (best == INT32_MAX) return 0;
    hit->owner = info[INFO * bestTriangle + 2];
    hit->part = info[INFO * bestTriangle + 3];
    return 1;
}

static double cpuSeconds(void) {
    struct timespec t;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static int byValue(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

int main(int argc, char **argv) {
    if (argc < 2) {
        fprintf(stderr, "usage: twin DIR [passes [prefetch]]\n");
        return 2;
    }
    const char *dir = argv[1];
    int passes = argc > 2 ? atoi(argv[2]) : 5;
    if (passes < 1 || passes > 64) passes = 5;
    int probe = argc > 3 && strcmp(argv[3], "prefetch") == 0;
    if (argc > 3 && !probe) {
        fprintf(stderr, "unknown probe %s: the only one is prefetch\n", argv[3]);
        return 2;
    }
    int32_t *header = load(dir, "header", NULL);
    for (int i = 0; i < LAYOUT_INTS; i++) {
        if (header[i] != LAYOUT[i]) {
            fprintf(stderr, "%s: layout constant %d is %d in the library, %d here; update twin.c\n", dir, i,
                    header[i], LAYOUT[i]);
            return 1;
        }
    }
    int32_t *h = header + LAYOUT_INTS;
    rootLink = h[0];
    rootCount = h[1];
    // The library's float[] starts 16 bytes past a cache line, and node 0 12 floats in, so every node fills whole
    // lines (BVH.FIRST_NODE): shift this copy by 4 floats to put node 0 on a line as well.
    float *raw = load(dir, "nodes", NULL);
    size_t nodeFloats = h[2], nodeBytes = ((nodeFloats + 4) * 4 + (1 << 21) - 1) / (1 << 21) * (1 << 21);
    nodes = aligned_alloc(1 << 21, nodeBytes);
    madvise(nodes, nodeBytes, MADV_HUGEPAGE);
    memcpy(nodes + 4, raw, nodeFloats * 4);
    free(raw);
    nodes += 4;
    triangles = load(dir, "triangles", NULL);
    info = load(dir, "info", NULL);
    const char *sets[2] = {"coherent", "incoherent"};
    for (int set = 0; set < 2; set++) {
        size_t bytes;
        double *flat = load(dir, sets[set], &bytes);
        char name[64];
        snprintf(name, sizeof name, "%s.t", sets[set]);
        double *expected = load(dir, name, NULL);
        int n = bytes / 48;
        Ray *rays = aligned_alloc(64, sizeof(Ray) * n);
        for (int i = 0; i < n; i++) {
            Ray *r = &rays[i];
            r->ox = flat[6 * i], r->oy = flat[6 * i + 1], r->oz = flat[6 * i + 2];
            r->dx = flat[6 * i + 3], r->dy = flat[6 * i + 4], r->dz = flat[6 * i + 5];
            derive(r);
        }
        Hit hit = {0};
        long mismatches = 0;
        for (int i = 0; i < n; i++) {
            double t = intersect(&rays[i], 0, INFINITY, &hit) ? hit.t : -1;
            if (memcmp(&t, &expected[i], 8) != 0) mismatches++;
        }
        // As the Java benchmark traces them: rays whose constants were derived beforehand. With "prefetch", the passes
        // alternate between the twin as it is and with prefetching, and the median of the pass-by-pass ratios is the
        // figure (the machine's drift cancels).
        double speeds[64], prefetched[64], ratios[64];
        long hits = 0;
        for (int p = -1; p < passes; p++) {
            for (int side = 0; side <= probe; side++) {
                prefetching = probe && ((p + side) & 1);
                double start = cpuSeconds();
                for (int i = 0; i < n; i++) hits += intersect(&rays[i], 0, INFINITY, &hit);
                double speed = n / (cpuSeconds() - start) / 1e6;
                if (p >= 0) *(prefetching ? &prefetched[p] : &speeds[p]) = speed;
            }
            if (p >= 0 && probe) ratios[p] = prefetched[p] / speeds[p];
        }
        qsort(speeds, passes, sizeof(double), byValue);
        printf("twin %s %s: %.2f M rays/CPU-s, %ld of %d distances differ from the library's%s\n", dir, sets[set],
                speeds[passes / 2], mismatches, n, hits < 0 ? " " : "");
        if (probe) {
            qsort(prefetched, passes, sizeof(double), byValue);
            qsort(ratios, passes, sizeof(double), byValue);
            printf("twin %s %s with prefetching: %.2f M rays/CPU-s, %.3fx the twin's (pass by pass, median)\n", dir,
                    sets[set], prefetched[passes / 2], ratios[passes / 2]);
        }
        free(rays);
    }
    return 0;
}
