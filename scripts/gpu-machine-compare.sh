#!/bin/bash
# On a GPU machine, over a bundle made by scripts/bundle-for-gpu-machine.sh
# DIR BASE_COMMIT: the GPU parity tests of the bundle's stochtex_tests (where
# it was packed), then the GPU benchmarks of the base and the current stochtex_bench in turn,
# ROUNDS times (so that clock and temperature drift fall on both alike), with
# the SM clock sampled beside them. Writes into OUT (at most 5 files) and
# prints each benchmark's current/base throughput ratio, median over rounds.
#
#   scripts/gpu-machine-compare.sh DIR OUT [ROUNDS]
set -uo pipefail
bundle=$(cd "${1:?usage: $0 DIR OUT [ROUNDS]}" && pwd)
out=${2:?usage: $0 DIR OUT [ROUNDS]}
rounds=${3:-3}
export LD_LIBRARY_PATH=$bundle/lib${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
benchmarks=${GPU_BENCH_FILTER:-'GpuShaderThroughput/mode:./size:2048/pipeline:.$|GpuLeanThroughput/size:2048$'}
# glslangValidator and image files are not on the machine (the bundle's note).
tests=${GPU_TEST_FILTER:-'Gpu.*:KernelParity.*:Shadertoy.*:-Gpu.ShadersValidate*:Gpu.Gaussianized*'}
mkdir -p "$out"
{
    date -u +%FT%TZ
    nvidia-smi --query-gpu=name,driver_version,clocks.max.sm,memory.total --format=csv
    grep -m1 'model name' /proc/cpuinfo
    echo "current $(cat "$bundle/commit")  base $(cat "$bundle/base_commit")"
} >"$out/machine.txt" 2>&1
nvidia-smi --query-gpu=timestamp,clocks.sm,temperature.gpu,utilization.gpu --format=csv -lms 500 >"$out/clocks.csv" 2>&1 &
sampler=$!
trap 'kill $sampler 2>/dev/null' EXIT
if [[ -x $bundle/bin/stochtex_tests ]]; then  # packed with BUNDLE_TESTS=1
    timeout 300 "$bundle/bin/stochtex_tests" --gtest_filter="$tests" >"$out/gpu_tests.log" 2>&1
    echo "parity tests: exit $? ($(grep -c '^\[       OK' "$out/gpu_tests.log") passed, $(grep -c '^\[  FAILED  \] [A-Z]' "$out/gpu_tests.log") failed lines)"
fi
runs=$(mktemp -d)
for r in $(seq "$rounds"); do
    for v in base current; do
        bin=$bundle/bin/stochtex_bench$([[ $v == base ]] && echo _base)
        "$bin" --benchmark_filter="$benchmarks" --benchmark_format=json --benchmark_out="$runs/${v}_$r.json" \
            >/dev/null 2>>"$out/bench_stderr.log" || echo "$v round $r: exit $?"
    done
done
tar -C "$runs" -cf "$out/bench.tar" .
python3 - "$runs" <<'PY'
import json, pathlib, statistics, sys
rates = {}  # (benchmark, counter) -> {version: [per-round values]}
for f in sorted(pathlib.Path(sys.argv[1]).glob("*.json")):
    version = f.stem.split("_")[0]
    for b in json.loads(f.read_text())["benchmarks"]:
        for k, v in b.items():
            if k.endswith("texel/s"):
                rates.setdefault((b["name"], k), {}).setdefault(version, []).append(v)
print(f"{'benchmark':58} {'counter':24} {'base':>8} {'current':>8} {'cur/base':>8}  per round")
for (name, counter), v in sorted(rates.items()):
    if len(v) < 2: continue
    ratios = [c / b for b, c in zip(v["base"], v["current"])]
    print(f"{name:58} {counter:24} {statistics.median(v['base']):8.4f} {statistics.median(v['current']):8.4f} "
          f"{statistics.median(ratios):8.3f}  " + " ".join(f"{r:.3f}" for r in ratios))
PY
