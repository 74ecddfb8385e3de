#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# A newcomer's first hour, scripted (#31): the README's hemoscale commands, every case folder with --quick, and five
# typical mistakes, each checked for its documented exit code and for a message that names the fix. Everything is
# written under a scratch folder; the repository's cases/ and data/ must be left as they were (git status, checked).
# Usage: scripts/walkthrough.sh [--build-dir DIR] [--mistakes-only] [--all] [--keep]
#   --mistakes-only  the README commands that take seconds and the five mistakes (the CTest walkthrough.mistakes)
#   --all            also the case folders whose --quick run is too long for CI (SLOW below, with the time measured)
#   --keep           keep the scratch folder (its path is printed)
# Exit 0 when every step gave what the docs promise, 1 otherwise (each failure is printed with the output's tail).
set -uo pipefail
cd "$(dirname "$0")/.."

build_dir=build
mode=default
keep=0
while [ $# -gt 0 ]; do
  case "$1" in
    --build-dir) build_dir="$2"; shift ;;
    --mistakes-only) mode=mistakes ;;
    --all) mode=all ;;
    --keep) keep=1 ;;
    *) echo "usage: scripts/walkthrough.sh [--build-dir DIR] [--mistakes-only] [--all] [--keep]" >&2; exit 2 ;;
  esac
  shift
done
hs="$(cd "$build_dir" 2>/dev/null && pwd)/app/hemoscale"
[ -x "$hs" ] || { echo "no $hs: build first (scripts/setup.sh)" >&2; exit 2; }
export OMP_WAIT_POLICY=passive   # spinning OpenMP threads slow everything else on a small machine

# Case folders whose --quick run takes more than ~60 s of CPU, skipped unless --all (measured on the 2-core
# development machine under load, 2026-12-02, user+sys CPU seconds). The others take 0.2-28 s each (migration/re-0.2
# 28 s, stenosis 22 and 25 s, migration 12 and 13 s, tube-lift 17 s, tube-drag 10 s); all 14: ~2.5 min of CPU.
declare -A SLOW=(
  [cases/resolved/tube-drag-fine]="--quick keeps dx = 0.5 um (105x105x100 nodes): ~185 s of CPU (3500 of its 4000 steps in 162 s)"
  [cases/resolved/tube-lift-fine]="--quick keeps dx = 0.5 um, as tube-drag-fine: ~3 min of CPU"
)
# Case folders whose --quick run ends with exit 1 by design (their own check fails; docs/testing.md says why): none.
# (tube-drag and tube-lift stop at --quick's cap before they settle; that check is skipped under --quick, exit 0.)
declare -A EXPECT_ONE=()

scratch=$(mktemp -d /tmp/hs_walkthrough.XXXXXX)
[ $keep -eq 1 ] || trap 'rm -rf "$scratch"' EXIT
repo_state() { git status --porcelain --untracked-files=all -- cases data 2>/dev/null; }
state_before=$(repo_state)
passed=0
failed=0
skipped=0

# step NAME EXPECTED_CODE PATTERN -- COMMAND...: runs COMMAND, checks its exit code and (if PATTERN is not empty)
# that its output matches the extended regex PATTERN.
step() {
  local name=$1 want=$2 pattern=$3
  shift 4
  local log="$scratch/log/${name//\//_}.txt"
  mkdir -p "$scratch/log"
  local t0=$SECONDS
  /usr/bin/time -f "%U %S" -o "$log.time" "$@" > "$log" 2>&1
  local code=$?
  local cpu
  cpu=$(tail -n 1 "$log.time" | awk '{printf "%.1f", $1 + $2}' 2>/dev/null)
  if [ "$code" -eq "$want" ] && { [ -z "$pattern" ] || grep -Eq -- "$pattern" "$log"; }; then
    printf 'ok    %-58s exit %s  %4ss wall %6ss cpu\n' "$name" "$code" $((SECONDS - t0)) "$cpu"
    passed=$((passed + 1))
  else
    printf 'FAIL  %-58s exit %s (want %s)%s\n' "$name" "$code" "$want" "${pattern:+, want output matching: $pattern}"
    tail -n 15 "$log" | sed 's/^/      | /'
    failed=$((failed + 1))
  fi
}

# check NAME CONDITION...: a check on files rather than on a command's output.
check() {
  local name=$1
  shift
  if "$@"; then printf 'ok    %s\n' "$name"; passed=$((passed + 1))
  else printf 'FAIL  %s\n' "$name"; failed=$((failed + 1)); fi
}

# A copy of a shipped case folder (without its runs/) with sed expression SED applied to its case.toml.
copy_case() {
  local from=$1 to=$2 sed_expr=${3:-}
  cp -a "$from" "$to"
  rm -rf "$to/runs"
  [ -z "$sed_expr" ] || sed -i -E "$sed_expr" "$to/case.toml"
}

echo "== the README's commands (scratch: $scratch)"
step "hemoscale --help" 0 "run" -- "$hs" --help
step "hemoscale --version" 0 "hemoscale" -- "$hs" --version
step "hemoscale run --help lists the case types" 0 "tube-poiseuille +plasma in a periodic tube" -- "$hs" run --help
step "campaign CAMPAIGN_DIR --status" 0 "" -- "$hs" campaign cases/campaign/tube-re-rstar --status
step "fit --check (the committed drag closure)" 0 "" -- "$hs" fit --check data/closures/resolved/drag_coefficient/cd_di_rep.toml
step "validate resolved-dataset (exit 1 on the committed dataset)" 1 "capped|outside|failed" -- \
  "$hs" validate resolved-dataset --json "$scratch/resolved-dataset.json"
step "run the default example --quick" 0 "" -- "$hs" run cases/resolved/tube-poiseuille --quick --quiet \
  --output "$scratch/default-example"
check "  its summary.json says quick" grep -q '"quick": true' "$scratch/default-example/summary.json"

echo "== five mistakes"
# 1. Micrometres given as metres: refused before anything is allocated, with the hint, and no run folder.
copy_case cases/resolved/tube-poiseuille "$scratch/m1" 's/^radius_m = 25\.0e-6/radius_m = 25.0/'
step "radius_m = 25.0 (micrometres meant)" 2 "25 micrometres is written 25e-6" -- "$hs" run "$scratch/m1" --quiet
check "  no run folder was made" test ! -e "$scratch/m1/runs"
# 2. A typo'd key: exit 2, "did you mean" with the right spelling.
copy_case cases/resolved/tube-poiseuille "$scratch/m2" 's/^kinematic_viscosity_m2_s/kinematic_viscosity_m2s/'
step "kinematic_viscosity_m2s (typo)" 2 "did you mean kinematic_viscosity_m2_s" -- "$hs" run "$scratch/m2" --quiet
check "  no run folder was made" test ! -e "$scratch/m2/runs"
# 3. --resume without a checkpoint: a finished run is complete and unchanged (exit 0); an unfinished one is refused.
sum_before=$(cd "$scratch/default-example" && find . -type f -exec sha256sum {} + | sort)
step "--resume of a finished run without a checkpoint" 0 "already complete" -- \
  "$hs" run cases/resolved/tube-poiseuille --quick --quiet --output "$scratch/default-example" --resume
check "  nothing in the finished run changed" test "$sum_before" = "$(cd "$scratch/default-example" && find . -type f -exec sha256sum {} + | sort)"
mkdir -p "$scratch/unfinished" && echo "started" > "$scratch/unfinished/log.txt"
step "--resume of an unfinished run without a checkpoint" 2 "checkpoint" -- \
  "$hs" run cases/resolved/tube-poiseuille --quick --quiet --output "$scratch/unfinished" --resume
check "  the unfinished run was left alone" test "$(ls "$scratch/unfinished")" = "log.txt"
# 4. A copied case folder: the CFD-DEM case names its closures by registered name ("resolved"), so a copy elsewhere
#    runs; a copy that names them by a relative path is refused with the missing file named.
copy_case cases/unresolved/tube-pries "$scratch/copied-tube-pries"
step "a copy of cases/unresolved/tube-pries elsewhere, --quick" 0 "" -- \
  "$hs" run "$scratch/copied-tube-pries" --quick --quiet --output "$scratch/copied-tube-pries-run"
copy_case cases/unresolved/tube-pries "$scratch/copied-by-path" \
  's|^drag = "resolved"|drag = "../../../data/closures/resolved/drag_coefficient/cd_di_rep.toml"|'
step "a copy naming its drag by relative path" 2 "drag.*cd_di_rep.toml" -- \
  "$hs" run "$scratch/copied-by-path" --quick --quiet --output "$scratch/copied-by-path-run"
check "  the refused copy wrote no run folder" test ! -e "$scratch/copied-by-path-run"
# 5. A campaign given its campaign.toml: accepted, --status writes nothing.
step "campaign DIR/campaign.toml --status" 0 "" -- "$hs" campaign cases/campaign/tube-re-rstar/campaign.toml --status

if [ "$mode" != mistakes ]; then
  echo "== every case folder with --quick"
  while IFS= read -r file; do
    dir=$(dirname "$file")
    name=${dir#cases/}
    if [ -n "${SLOW[$dir]:-}" ] && [ "$mode" != all ]; then
      printf 'skip  %-58s %s (--all runs it)\n' "$dir" "${SLOW[$dir]}"
      skipped=$((skipped + 1))
      continue
    fi
    want=0
    [ -z "${EXPECT_ONE[$dir]:-}" ] || want=1
    step "$dir --quick${EXPECT_ONE[$dir]:+ (exit 1: ${EXPECT_ONE[$dir]})}" "$want" "" -- \
      "$hs" run "$dir" --quick --quiet --output "$scratch/cases/$name"
    check "  $name: summary.json says quick" grep -q '"quick": true' "$scratch/cases/$name/summary.json"
  done < <(find cases -name case.toml -not -path '*/runs/*' | sort)
fi

check "the repository's cases/ and data/ are as they were" test "$state_before" = "$(repo_state)"
echo "== $passed passed, $failed failed, $skipped skipped"
[ "$failed" -eq 0 ]
