#!/bin/sh
# SPDX-License-Identifier: MIT
# header_sections.sh: each section header of the public API (include/orbillum/*.h)
# compiles alone, included twice (its guard), in both precisions and with every
# option that removes declarations, under the library's warnings; and the
# umbrella include/orbillum.h compiles the same way.
#   tests/c/header_sections.sh [CC]
# Exit 0 when every one compiles.
set -u
CC=${1:-cc}
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
FLAGS="-std=c99 -Wall -Wextra -Wpedantic -Wconversion -Wshadow -Wdouble-promotion -Werror -Iinclude"
NO="-DOI_NO_EARTH_TABLE -DOI_NO_EARTH_ANGULAR -DOI_NO_MOON -DOI_NO_EXPOSURE -DOI_NO_ATMOSPHERE \
-DOI_NO_SKY -DOI_NO_LIMB_DARKENING -DOI_NO_FACETS -DOI_NO_OBLATE -DOI_NO_ALBEDO_MODELS \
-DOI_NO_SKYLIGHT -DOI_NO_TOTAL_BAND"
fail=0
n=0
set -- include/orbillum/*.h
[ -e "$1" ] || { echo "FAIL: no section header in include/orbillum/"; exit 1; }
for h in "$@" orbillum.h; do
    inc=${h#include/}
    # a declaration of its own: a header emptied by an option leaves no empty unit
    printf '#include "%s"\n#include "%s"\nint header_sections_probe(void);\n' "$inc" "$inc" \
        >"$T/probe.c"
    for defs in "" "-DOI_SINGLE_PRECISION" "$NO" "-DOI_SINGLE_PRECISION $NO"; do
        n=$((n + 1))
        # shellcheck disable=SC2086
        if ! $CC $FLAGS $defs -c "$T/probe.c" -o "$T/probe.o" >"$T/log" 2>&1; then
            echo "FAIL: $inc alone does not compile with [${defs:-double}]"; cat "$T/log"; fail=1
        fi
    done
done
[ $fail = 0 ] && echo "ok: $# section headers and orbillum.h, each alone, compile ($n builds)"
exit $fail
