#!/usr/bin/env bash
# What CI runs for issue 5 (stability): the C tests under ASan + UBSan, the
# static analysers, a short fuzz run of every target (after replaying the
# committed regression corpus). Each make target installs what it needs.
set -euo pipefail
cd "$(dirname "$0")/.."
export DEBIAN_FRONTEND=noninteractive
make sanitize
make analyze
make fuzz-ci FUZZ_CI_SECONDS="${FUZZ_CI_SECONDS:-15}"
