#!/usr/bin/env bash
# The README's five-minute tour, run as written: takes the one ```sh block under the heading
# '## Five-minute tour' of README.md and runs it with 'set -euo pipefail' in a fresh temporary
# folder, with the built tactip first on PATH. Without a display it runs under 'xvfb-run -a'.
# Any command of the tour that fails fails the test. Run by ctest (SKIP_RETURN_CODE 77).
#
# Usage: readme_tour_test.sh TACTIP_BINARY SOURCE_DIR
# Exit: 0 pass, 1 fail, 77 skip (xvfb-run missing: the tour renders a screenshot with it).
set -euo pipefail

tactip=$1
src=$2
readme="$src/README.md"

skip() { echo "SKIP: $*"; exit 77; }
fail() { echo "FAIL: $*" >&2; exit 1; }

[ -x "$tactip" ] || fail "tactip binary '$tactip' not found"
[ -f "$readme" ] || fail "'$readme' not found"
command -v xvfb-run >/dev/null || skip "xvfb-run not found (Debian package xvfb): the tour renders its screenshot under xvfb-run -a"

work=$(mktemp -d "${TMPDIR:-/tmp}/tactip-readme-tour.XXXXXX")
trap 'rm -rf "$work"' EXIT

# The tour: the sh blocks between '## Five-minute tour' and the next '## ' heading (headings
# are looked for outside code blocks only); there must be exactly one.
blocks=$(awk -v out="$work/tour-block.sh" '
  /^```/ {
    if (infence) { infence = 0; capture = 0 }
    else { infence = 1; if (insec && $0 ~ /^```sh[[:space:]]*$/) { capture = 1; n++ } }
    next
  }
  infence { if (capture) print > out; next }
  /^## / { insec = ($0 ~ /^## Five-minute tour[[:space:]]*$/) }
  END { if (infence) print "unclosed"; else print n + 0 }
' "$readme")
[ "$blocks" = 1 ] || fail "README.md: expected one \`\`\`sh block under '## Five-minute tour', found $blocks"

{
  echo 'set -euo pipefail'
  echo 'set -x'
  cat "$work/tour-block.sh"
} >"$work/tour.sh"

mkdir "$work/run"
cd "$work/run"
bindir=$(cd "$(dirname "$tactip")" && pwd)
export PATH="$bindir:$PATH"
# A tactip built from this tree finds the plotting script in it; a copied binary finds it here.
export TACTIP_SCRIPTS_DIR="${TACTIP_SCRIPTS_DIR:-$src/scripts}"

start=$(date +%s)
status=0
if [ -z "${DISPLAY:-}" ]; then
  xvfb-run -a bash "$work/tour.sh" || status=$?
else
  bash "$work/tour.sh" || status=$?
fi
elapsed=$(($(date +%s) - start))
[ "$status" -eq 0 ] || fail "a command of the README's tour failed (exit $status; the failing command is the last one traced above)"
echo "PASS: the README's five-minute tour ran as written in ${elapsed} s ($(grep -cE '^(xvfb-run -a )?tactip ' "$work/tour-block.sh") tactip commands)"
