#!/usr/bin/env bash
# Every documented option exists. For every tactip command line in README.md and docs/*.md
# (a line of a code block that starts, after optional spaces, '$ ', 'xvfb-run -a ' or
# 'build/release/', with 'tactip ' and a word; also every inline `tactip ...` code span),
# takes the subcommand (and, for run, validate and report, the second word; 'a|b' names
# alternatives) and checks that every --option on the line appears in the output of
# 'tactip SUB [SUB2] --help'. In code blocks lines ending in '\' are joined with the next and
# a '# comment' is ignored. Prints each offending line and exits 1. Run by ctest.
#
# Usage: doc_commands_test.sh TACTIP_BINARY SOURCE_DIR
set -euo pipefail

tactip=$1
src=$2

fail() { echo "FAIL: $*" >&2; exit 1; }
[ -x "$tactip" ] || fail "tactip binary '$tactip' not found"

files=("$src/README.md" "$src"/docs/*.md)
for f in "${files[@]}"; do [ -f "$f" ] || fail "'$f' not found"; done

# The help text of 'tactip ARGS --help', cached by the words before --help.
declare -A help_text help_rc
help() {
  local key="$*"
  [ -n "$key" ] || key=.
  if [ -z "${help_rc[$key]+set}" ]; then
    local rc=0 out
    out=$("$tactip" "$@" --help 2>&1) || rc=$?
    help_text[$key]=$out
    help_rc[$key]=$rc
  fi
  current=$key
}
has_word() { grep -qE -- "(^|[^A-Za-z0-9-])$1([^A-Za-z0-9-]|$)" <<<"$2"; }
has_option() { grep -qE -- "(^|[[:space:],])$1([[:space:],=]|$)" <<<"$2"; }

# The subcommands a help text lists (the words starting the lines under 'Subcommands:').
subcommands() { awk '/^Subcommands:/ { on = 1; next } on && /^  [a-z]/ { print $1 }' <<<"$1"; }
help; top_subs=" $(subcommands "${help_text[.]}" | tr '\n' ' ')"
help run; run_subs=" $(subcommands "${help_text[run]}" | tr '\n' ' ')"
if [ "$top_subs" = " " ] || [ "$run_subs" = " " ]; then
  fail "cannot read the subcommands from 'tactip --help' and 'tactip run --help'"
fi

checked=0
bad=0
report() { echo "$1: $2"; echo "    $3"; bad=$((bad + 1)); }

# KIND<TAB>FILE:LINE<TAB>TEXT: 'block' for a code-block line (continuations joined), 'span'
# for an inline code span (a span may run over several lines of a paragraph).
extract() {
  awk '
    function flush(   rest, off, pos, len, span, k, line) {
      rest = para; off = 0
      while (match(rest, /`[^`]+`/)) {
        pos = off + RSTART; len = RLENGTH
        span = substr(rest, RSTART + 1, RLENGTH - 2)
        line = pstart
        for (k = 1; k <= nlines; k++) if (pos > ends[k]) line = pstart + k
        printf "span\t%s:%d\t%s\n", pfile, line, span
        off += RSTART + RLENGTH - 1
        rest = substr(rest, RSTART + RLENGTH)
      }
      para = ""; nlines = 0
    }
    FNR == 1 { if (para != "") flush(); infence = 0; buf = ""; para = ""; nlines = 0 }
    /^[[:space:]]*```/ { if (!infence) flush(); infence = !infence; buf = ""; next }
    infence {
      line = $0
      if (buf != "") line = buf " " line; else start = FNR
      if (line ~ /\\$/) { sub(/\\$/, "", line); buf = line; next }
      buf = ""
      printf "block\t%s:%d\t%s\n", FILENAME, start, line
      next
    }
    /^[[:space:]]*$/ { flush(); next }
    {
      if (para == "") { pfile = FILENAME; pstart = FNR; para = $0 } else para = para " " $0
      ends[++nlines] = length(para)
    }
    END { flush() }
  ' "$@"
}

re='^[[:space:]]*(\$[[:space:]]+)?(xvfb-run[[:space:]]+-a[[:space:]]+)?(build/release/)?tactip[[:space:]]([^[:space:]].*)$'
while IFS=$'\t' read -r kind where text; do
  [[ $text =~ $re ]] || continue
  cmd=${BASH_REMATCH[4]}
  if [ "$kind" = block ]; then
    cmd=${cmd%%[[:space:]]#*}                    # drop a trailing '# comment'
  fi
  cmd=${cmd//\\|/|}                              # '\|' in a table cell
  for sep in ' | ' ' && ' ' ; ' ' > '; do cmd=${cmd%%"$sep"*}; done   # this command only
  read -ra words <<<"$cmd"
  sub=${words[0]}
  sub2=${words[1]:-}
  sub2=${sub2//[\[\]]/}
  [[ $sub2 == -* ]] && sub2=
  # A placeholder (tactip SUBCOMMAND ...) in running text is not a command.
  if [[ ! $sub =~ ^(-|[a-z][a-z0-9-]*$) ]]; then
    [ "$kind" = span ] && continue
    report "$where" "'$sub' is not a tactip subcommand" "$text"
    continue
  fi
  checked=$((checked + 1))
  if [[ $sub != -* && $top_subs != *" $sub "* ]]; then
    report "$where" "'$sub' is not a tactip subcommand (see 'tactip --help')" "$text"
    continue
  fi

  keys=()
  if [[ $sub == -* ]]; then
    help; keys+=("$current")
  elif [ "$sub" = run ]; then
    if [ -z "$sub2" ]; then
      help run; keys+=("$current")
    else
      IFS='|' read -ra alts <<<"$sub2"
      for a in "${alts[@]}"; do
        [[ $run_subs == *" $a "* ]] ||
          { report "$where" "'$a' is not a protocol of 'tactip run' (see 'tactip run --help')" "$text"; continue; }
        help run "$a"; keys+=("$current")
      done
    fi
  else
    help "$sub"; keys+=("$current")
  fi
  ok=1
  for key in "${keys[@]}"; do
    if [ "${help_rc[$key]}" -ne 0 ]; then
      report "$where" "'tactip ${key#.} --help' fails: $(head -n 1 <<<"${help_text[$key]}")" "$text"
      ok=0
    fi
  done
  [ "$ok" = 1 ] || continue
  if { [ "$sub" = validate ] || [ "$sub" = report ]; } && [ -n "$sub2" ]; then
    IFS='|' read -ra alts <<<"$sub2"
    for a in "${alts[@]}"; do
      [[ $a =~ ^[a-z][a-z0-9-]*$ ]] || continue  # FILE, WHAT: placeholders
      has_word "$a" "${help_text[$sub]}" ||
        report "$where" "'$a' is not something 'tactip $sub' does (see 'tactip $sub --help')" "$text"
    done
  fi
  for w in "${words[@]}"; do
    [[ $w =~ ^[\[\(]*(--[A-Za-z][A-Za-z0-9-]*) ]] || continue
    opt=${BASH_REMATCH[1]}
    for key in "${keys[@]}"; do
      has_option "$opt" "${help_text[$key]}" ||
        report "$where" "$opt is not an option of 'tactip ${key#.}' (see its --help)" "$text"
    done
  done
done < <(extract "${files[@]}")

[ "$checked" -gt 0 ] || fail "no tactip command found in README.md and docs/*.md"
if [ "$bad" -gt 0 ]; then
  echo "FAIL: $bad documented command line(s) name an option or subcommand tactip does not have ($checked checked)"
  exit 1
fi
echo "PASS: every option of the $checked tactip command lines of README.md and docs/*.md exists (${#help_rc[@]} help texts read)"
