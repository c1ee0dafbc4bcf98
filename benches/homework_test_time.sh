#!/usr/bin/env bash
# From an edit of a homework to its own test's result: the time a student waits in the loop
# "edit examples/hw1.rs, run `cargo test --release --example hw1`" (docs/tests.md, "A homework's own test").
#
#   benches/homework_test_time.sh            # from the workbook's folder (CARGO_TARGET_DIR is respected)
#
# The homework is the API page's, docs/homework_glossy.rs (a glossy mirror averaging N rays, with the test
# module the page shows), copied to examples/hw_timing.rs and removed at the end. It is built and tested once
# first, not timed (the library and the dependencies are built then, as they are after a student's first
# run). Then two edits are timed, each from the moment the file is written to the test's result:
#   1. a correct edit (another glossiness): the test passes;
#   2. the naive sum (its N rays added up and not divided by N): the test fails, naming the shader.
# Each prints its wall time and the CPU time of cargo, rustc and the test (user + system, children included),
# and the machine's load average before it: on a machine shared with other work the wall time grows with the
# load, the CPU time much less.
set -euo pipefail
cd "$(dirname "$0")/.."

name=hw_timing
file=examples/$name.rs
if [ -e "$file" ]; then
    echo "$file exists: not overwriting it" >&2
    exit 2
fi
trap 'rm -f "$file"' EXIT INT TERM

mean='sum \* self.tint / kept as f32'
grep -q "$mean" docs/homework_glossy.rs || { echo "docs/homework_glossy.rs no longer averages as expected" >&2; exit 2; }

cp docs/homework_glossy.rs "$file"
echo "first build and test of $file (not timed) ..."
cargo test --release --example "$name" >/dev/null 2>&1

# Runs the homework's test after the edit `sed_expression` of the page's homework; prints the times and
# whether the test passed.
timed_edit() {
    local what=$1 sed_expression=$2 expect=$3 load result
    load=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo "?")
    local TIMEFORMAT='%R %U %S'
    local times
    times=$( { time {
        sed -e "$sed_expression" docs/homework_glossy.rs > "$file"
        if cargo test --release --example "$name" >/tmp/homework_test_time.$$ 2>&1; then result=passed; else result=failed; fi
        echo "$result" > /tmp/homework_test_time.$$.result
    } ; } 2>&1 )
    result=$(cat /tmp/homework_test_time.$$.result)
    rm -f /tmp/homework_test_time.$$ /tmp/homework_test_time.$$.result
    read -r wall user system <<< "$times"
    cpu=$(awk "BEGIN { print $user + $system }")
    printf '%-40s %6.1f s wall, %6.1f s CPU (%s user + %s system); test %s (expected: %s); load average before: %s\n' \
        "$what" "$wall" "$cpu" "$user" "$system" "$result" "$expect" "$load"
    [ "$result" = "$expect" ]
}

echo "$(nproc) cores"
timed_edit "edit: glossiness 0.9 -> 0.85" 's/glossiness: 0.9,/glossiness: 0.85,/' passed
timed_edit "edit: the naive sum (not divided by N)" "s|$mean|sum * self.tint|" failed
