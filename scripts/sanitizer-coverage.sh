#!/bin/sh
# sanitizer-coverage.sh - what `make asan` leaves out costs no coverage: build the suite with gcov,
# run the tiers the sanitizer build runs (unit, proc) and then the whole `make test` selection
# (unit, proc, image), and list every function the whole suite executes that the sanitizer
# selection does not. Exit 1 when a source file the suite executes is not executed at all by the
# sanitizer selection, 0 otherwise (functions left out are listed either way).
#
#   sh scripts/sanitizer-coverage.sh            # builds build/cov, ~2x the time of `make unit`
set -eu
cd "$(dirname "$0")/.."
B=build/cov
JOBS=${JOBS:-$(nproc 2>/dev/null || echo 2)}
make --no-print-directory -j"$JOBS" BUILD=$B BIN=$B/waterworld OPT="-O0 -g --coverage" \
    $B/waterworld $B/ww-tests $(for t in scene obj png inflate exr wav image; do echo $B/fuzz-replay/fuzz_$t; done) >/dev/null

# functions with at least one line executed, as "file function", from the .gcda files present
executed() {
    find $B/src -name '*.gcda' | sort | while read -r gcda; do
        obj=${gcda%.gcda}.o
        src=${obj#$B/}
        src=${src%.o}.c
        (cd "$(dirname "$gcda")" && gcov -f -n -o . "$OLDPWD/$src" 2>/dev/null) |
            awk -v f="$src" '/^Function /{fn=$2; gsub("\047","",fn)} /^Lines executed:/{
                if (fn != "" && $2 !~ /^0.00%/) print f, fn; fn=""}'
    done | sort -u
}

run() {
    find $B -name '*.gcda' -delete
    WW_BIN=./$B/waterworld $B/ww-tests -j "$JOBS" --tier "$1" >/dev/null 2>&1 || true
    executed > "$B/executed-$2.txt"
}

run unit,proc sanitizer
run test whole
comm -13 "$B/executed-sanitizer.txt" "$B/executed-whole.txt" > "$B/left-out.txt"
files_whole=$(cut -d' ' -f1 "$B/executed-whole.txt" | sort -u)
files_san=$(cut -d' ' -f1 "$B/executed-sanitizer.txt" | sort -u)
missing=$(printf '%s\n' "$files_whole" | comm -23 - "$(printf '%s\n' "$files_san" > $B/f.txt; echo $B/f.txt)")
echo "functions executed: whole suite $(wc -l < $B/executed-whole.txt), sanitizer selection $(wc -l < $B/executed-sanitizer.txt)"
echo "source files executed: whole suite $(printf '%s\n' "$files_whole" | wc -l), sanitizer selection $(printf '%s\n' "$files_san" | wc -l)"
if [ -s "$B/left-out.txt" ]; then
    echo "functions only the image tier executes:"
    sed 's/^/  /' "$B/left-out.txt"
else
    echo "functions only the image tier executes: none"
fi
if [ -n "$missing" ]; then
    echo "source files the sanitizer selection never executes:"
    printf '  %s\n' $missing
    exit 1
fi
