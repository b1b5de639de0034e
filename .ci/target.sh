#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# CI for the flight target: cross toolchain and qemu are installed by
# `make deps-cross` (apt-get, mk/deps.mk) when missing; then the runtime is built for
# Cortex-M4F (float) and Cortex-M7 (double), measured, and the self-test
# images run under qemu-system-arm. Called by .ci/run.
set -euo pipefail
cd "$(dirname "$0")/.."
export DEBIAN_FRONTEND=noninteractive
JOBS="${CI_JOBS:-2}"
make deps-cross
make -j"$JOBS" cross
make -j"$JOBS" size
make -j"$JOBS" stack
make -j"$JOBS" target-test
make -j"$JOBS" target-bench
