#!/usr/bin/env bash
# The clang-tidy stage (scripts/tidy.py) on a two-file tree of its own: what the committed
# record of clean units lets it skip, and what it must still analyse.
#   1. a tree analysed and recorded clean is, on a machine with nothing cached, not analysed
#      again (the record alone says it is clean);
#   2. a finding put into a header, while the unit that includes it is unchanged since the
#      recorded run, is reported: the unit's key follows its headers;
#   3. a unit that was never analysed (added after the record) is analysed;
#   4. --record refuses to write a record while anything is reported.
# Usage: tidy_stage_test.sh SOURCE_DIR   (the project's tree: its .clang-tidy and scripts/)
set -euo pipefail
project="$(cd "${1:?usage: tidy_stage_test.sh SOURCE_DIR}" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
tree="$work/tree"
mkdir -p "$tree/sim" "$tree/build"
cp "$project/.clang-tidy" "$tree/"

cat >"$tree/sim/widget.h" <<'EOF'
#pragma once
inline int* firstSlot(int* slots) { return slots; }
EOF
cat >"$tree/sim/widget.cpp" <<'EOF'
#include "widget.h"
int sum(int* slots) { return *firstSlot(slots) + 1; }
EOF
database() {
  local entries=() f
  for f in "$@"; do
    entries+=("{\"directory\": \"$tree/build\", \"file\": \"$tree/sim/$f\",
      \"command\": \"/usr/bin/c++ -std=c++20 -I$tree/sim -o $f.o -c $tree/sim/$f\"}")
  done
  local IFS=,
  printf '[%s]\n' "${entries[*]}" >"$tree/build/compile_commands.json"
}
database widget.cpp

tidy() {  # tidy CACHE_NAME [--record] → output in $work/out, status in $status
  status=0
  python3 "$project/scripts/tidy.py" --src "$tree" --build "$tree/build" \
    --cache "$work/$1" --verified "$tree/verified.txt" "${@:2}" >"$work/out" 2>&1 || status=$?
}
fail() { echo "FAIL: $*"; cat "$work/out"; exit 1; }

tidy first --record
[ "$status" -eq 0 ] || fail "the clean tree was not reported clean"
grep -q '^tidy: 1 files: 1 analysed' "$work/out" || fail "the first run did not analyse the unit"
grep -q ' sim/widget.cpp$' "$tree/verified.txt" || fail "the record does not list sim/widget.cpp"

# 1. nothing cached (a fresh cache dir), the record says the unit is clean
tidy cold1
[ "$status" -eq 0 ] || fail "the recorded tree was not clean"
grep -q '^tidy: 1 files: 0 analysed, 1 verified clean' "$work/out" ||
  fail "a recorded unit was analysed again"

# 2. a finding (modernize-use-nullptr) in the header only; widget.cpp is unchanged
sed -i 's/return slots;/return slots != 0 ? slots : 0;/' "$tree/sim/widget.h"
tidy cold2
[ "$status" -eq 1 ] || fail "a finding in a changed header was not reported (exit $status)"
grep -q 'sim/widget.h:2:.*\[modernize-use-nullptr\]' "$work/out" ||
  fail "the header's finding is not in the output"
grep -q '^tidy: 1 files: 1 analysed, 0 verified clean' "$work/out" ||
  fail "the unit whose header changed was not analysed"

# 4. --record writes nothing while a finding stands
cp "$tree/verified.txt" "$work/before.txt"
tidy cold3 --record
[ "$status" -eq 1 ] || fail "--record succeeded with a finding"
cmp -s "$tree/verified.txt" "$work/before.txt" || fail "--record rewrote the record despite a finding"

# 3. the header mended; a unit added after the record is analysed, the recorded one is not
sed -i 's/return slots != 0 ? slots : 0;/return slots;/' "$tree/sim/widget.h"
cat >"$tree/sim/gadget.cpp" <<'EOF'
int twice(int x) { return 2 * x; }
EOF
database widget.cpp gadget.cpp
tidy cold4
[ "$status" -eq 0 ] || fail "the mended tree was not clean"
grep -q '^tidy: analysed sim/gadget.cpp$' "$work/out" || fail "the new unit was not analysed"
if grep -q '^tidy: analysed sim/widget.cpp$' "$work/out"; then
  fail "the recorded unit was analysed again"
fi
# 5. --known-only analyses nothing and records only what is known clean: a third unit never
#    analysed stays out of the record; the two known clean (cached by cold4) stay in
cat >"$tree/sim/gizmo.cpp" <<'EOF'
int thrice(int x) { return 3 * x; }
EOF
database widget.cpp gadget.cpp gizmo.cpp
tidy cold4 --record --known-only
[ "$status" -eq 0 ] || fail "--known-only failed (exit $status)"
if grep -q '^tidy: analysed' "$work/out"; then fail "--known-only analysed a unit"; fi
grep -q '^tidy: 2 of 3 units known clean, 1 not yet analysed' "$work/out" || fail "--known-only miscounted"
grep -q ' sim/gadget.cpp$' "$tree/verified.txt" || fail "the partial record lost sim/gadget.cpp"
if grep -q ' sim/gizmo.cpp$' "$tree/verified.txt"; then fail "the partial record holds a unit never analysed"; fi
echo "tidy stage: record honoured, header change analysed, new unit analysed, --record refused on a finding, --known-only records only what is known clean"
