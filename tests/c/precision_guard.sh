#!/bin/sh
# SPDX-License-Identifier: MIT
# precision_guard.sh: a program compiled for one precision links only with
# the archive of that precision (include/oi_config.h, the _sp names).
#   tests/c/precision_guard.sh [BUILDDIR] [CC]
# Links tests/c/precision_guard.c four ways: the two matched pairs must link
# and run; float code against the double archive must fail naming
# `oi_illuminate_sp', double code against the float archive naming
# `oi_illuminate'. Exit 0 when all four behave so.
set -u
B=${1:-build}
CC=${2:-cc}
SRC=tests/c/precision_guard.c
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
FLAGS="-std=c99 -Wall -Wextra -Werror -Iinclude"
fail=0

link() { # $1 = defines, $2 = archive, $3 = output
    $CC $FLAGS $1 $SRC "$2" -lm -o "$3" >"$T/log" 2>&1
}

for pair in "|$B/liborbillum.a|double" "-DOI_SINGLE_PRECISION|$B/float/liborbillum.a|float"; do
    defs=${pair%%|*}; rest=${pair#*|}; lib=${rest%%|*}; name=${rest#*|}
    if link "$defs" "$lib" "$T/ok" && "$T/ok" >/dev/null; then
        echo "ok: $name code links and runs with $lib"
    else
        echo "FAIL: $name code does not link or run with $lib"; cat "$T/log"; fail=1
    fi
done

if link "-DOI_SINGLE_PRECISION" "$B/liborbillum.a" "$T/bad"; then
    echo "FAIL: float code linked against the double archive"; fail=1
elif grep -qE "reference to .oi_illuminate_sp[^_a-z0-9]" "$T/log"; then
    echo "ok: float code against the double archive: $(grep -m1 -o "undefined reference to .oi_illuminate_sp." "$T/log")"
else
    echo "FAIL: float code against the double archive failed without naming oi_illuminate_sp"; cat "$T/log"; fail=1
fi

if link "" "$B/float/liborbillum.a" "$T/bad"; then
    echo "FAIL: double code linked against the float archive"; fail=1
elif grep -qE "reference to .oi_illuminate[^_a-z0-9]" "$T/log"; then
    echo "ok: double code against the float archive: $(grep -m1 -oE "undefined reference to .oi_illuminate[^_a-z0-9]" "$T/log")"
else
    echo "FAIL: double code against the float archive failed without naming oi_illuminate"; cat "$T/log"; fail=1
fi
exit $fail
