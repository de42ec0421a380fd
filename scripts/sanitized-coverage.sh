#!/usr/bin/env bash
# Which project source files the sanitized suite runs: builds a coverage tree (gcc --coverage,
# -O0, build/coverage), runs the tests the `sanitize` test preset runs (its exclusions, and the
# long physics experiments skipped as they are there), then prints every source file under sim/,
# models/, sensors/, detectors/ and scenarios/ with the share of its lines executed. Exit 1 if
# any file has no executed line. Not part of CI (a third build); see docs/tests.md.
#
#   bash scripts/sanitized-coverage.sh            # about 20 minutes on 2 cores
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build="$root/build/coverage"
exclude=$(python3 -c "import json,sys; d=json.load(open('$root/CMakePresets.json')); \
print(next(t['filter']['exclude']['name'] for t in d['testPresets'] if t['name']=='sanitize'))")

cmake -S "$root" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Debug -DTACTIP_BUILD_BENCHMARKS=OFF \
  -DCMAKE_UNITY_BUILD=ON -DCMAKE_UNITY_BUILD_BATCH_SIZE=16 \
  -DCMAKE_CXX_FLAGS="--coverage -O0" -DCMAKE_C_FLAGS="--coverage -O0" \
  -DCMAKE_EXE_LINKER_FLAGS=--coverage -DCMAKE_SHARED_LINKER_FLAGS=--coverage > /dev/null
cmake --build "$build" -j 2
find "$build" -name '*.gcda' -delete
TACTIP_SKIP_LONG_EXPERIMENTS=1 ctest --test-dir "$build" -j 2 -E "$exclude" --output-on-failure || true

# gcov's summary for every object: "File '/path'" then "Lines executed:P% of N".
report=$(cd "$build" && find . -name '*.gcda' -print0 | xargs -0 -I{} sh -c \
  'gcov -n -o "$(dirname "{}")" "{}" 2>/dev/null' | awk -v root="$root/" '
    /^File / { f = $2; gsub("\047", "", f); next }
    /^Lines executed:/ && index(f, root) == 1 {
      split($2, a, ":"); pct = a[2] + 0; n = $4 + 0; rel = substr(f, length(root) + 1)
      if (rel ~ /^(sim|models|sensors|detectors|scenarios)\// && rel ~ /\.(cpp|c)$/) {
        hit = pct * n / 100; if (!(rel in lines) || hit > best[rel]) { best[rel] = hit; lines[rel] = n }
      }
    }
    END { for (r in lines) printf "%6.1f%% of %5d lines  %s\n", (lines[r] ? 100 * best[r] / lines[r] : 0), lines[r], r }' | sort -k5)
echo "$report"
sources=$(cd "$root" && git ls-files 'sim/*.cpp' 'models/*.cpp' 'sensors/*.cpp' 'detectors/*.cpp' 'scenarios/*.cpp' \
  | grep -v '^scenarios/app/speed_benchmarks/')
missing=0
for s in $sources; do
  line=$(grep -F "  $s" <<< "$report" || true)
  if [ -z "$line" ] || [[ "$line" == "   0.0%"* ]]; then echo "not run under the sanitized selection: $s"; missing=1; fi
done
[ "$missing" -eq 0 ] && echo "sanitized-coverage: every source file runs ($(wc -w <<< "$sources") files)"
exit "$missing"
