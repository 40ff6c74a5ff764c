#!/usr/bin/env bash
# The closest-hit kernel's C twin beside the library and, where its anchor is set up, Embree: one thread each, the
# three alternated per round, M rays per CPU-second (docs/BENCHMARKS.md, "27 Nov, 14:00-14:40 UTC: the kernel's C
# twin").
#
#   benchmarks/kernel-twin/run.sh [ROUNDS] [WORKLOADS]
#
# ROUNDS defaults to 3, WORKLOADS to the four meshes of the BVH benchmark. Needs Linux, gcc and a CPU with AVX2 and FMA;
# Embree runs if ../embree-venv and ../shared/anchors/embree_bench.py exist (../shared/anchors/README.md). The
# exported arrays go to target/kernel-twin (120-240 MB per mesh).
set -euo pipefail
cd "$(dirname "$0")/../.."
rounds=${1:-3}
workloads=${2:-heightfield-100k,heightfield-1M,icosphere-82k,icosphere-1.3M}
out=target/kernel-twin
mkdir -p "$out"

mvn -q test-compile
java=(java -Xms4g -Xmx4g -XX:+AlwaysPreTouch -XX:+UseTransparentHugePages --add-modules jdk.incubator.vector
    -cp target/test-classes:target/classes geometries.KernelTwinExport)
# The library's side: its standard error (the incubator module's warning) is shown only if it fails.
library() {
    "${java[@]}" "$@" 2>"$out/library.err" || { cat "$out/library.err" >&2; exit 1; }
}
gcc -O2 -mavx2 -mfma -ffp-contract=off -o "$out/twin" benchmarks/kernel-twin/twin.c -lm

for w in ${workloads//,/ }; do library "$out/$w" "$w" 0; done

python=../embree-venv/bin/python
anchor=../shared/anchors/embree_bench.py
for r in $(seq 1 "$rounds"); do
    echo "round $r ($(date -u +%H:%M:%S) UTC)"
    if [[ -x $python && -f $anchor ]]; then
        if ! "$python" "$anchor" 1 "$out/embree-$r.json" >"$out/embree-$r.log" 2>&1; then
            echo "Embree's run failed: see $out/embree-$r.log" >&2
            exit 1
        fi
        "$python" - "$out/embree-$r.json" <<'EOF'
import json, sys
for e in json.load(open(sys.argv[1])):
    for rays in ("coherent", "incoherent"):
        print(f"embree {e['mesh']} {e['tris']} triangles {rays}: {e[rays + '_1t_Mrays_per_cpu_s']:.2f} M rays/CPU-s")
EOF
    fi
    for w in ${workloads//,/ }; do "$out/twin" "$out/$w" 5; done
    for w in ${workloads//,/ }; do library "$out/$w" "$w" 5 time-only; done
done
