#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# CI for the flight target: cross toolchain and qemu are installed by
# `make deps-cross` (apt-get, mk/deps.mk) when missing; then the runtime is built for
# Cortex-M4F (float) and Cortex-M7 (double), measured, and the self-test
# images run under qemu-system-arm. Called by .ci/run.
set -euo pipefail
cd "$(dirname "$0")/.."
export DEBIAN_FRONTEND=noninteractive
make deps-cross
make cross
make size
make stack
make target-test
make target-bench
