#!/usr/bin/env bash
# CI for stability: the C tests under ASan + UBSan, the static analysers, a
# short fuzz run of every target (after replaying the committed regression
# corpus). Each make target installs what it needs. Called by .ci/run.
set -euo pipefail
cd "$(dirname "$0")/.."
export DEBIAN_FRONTEND=noninteractive
JOBS="${CI_JOBS:-2}"
make -j"$JOBS" sanitize
make -j"$JOBS" analyze
make -j"$JOBS" fuzz-ci FUZZ_CI_SECONDS="${FUZZ_CI_SECONDS:-15}"
