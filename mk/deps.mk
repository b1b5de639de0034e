# SPDX-License-Identifier: MIT
# mk/deps.mk: what the host needs, installed on demand so that a fresh Debian machine needs only
# the make targets. Debian packages go through one macro (apt_need); the Python tools come
# from requirements.lock (exact versions) into $(VENV).
#
#   make deps          cmocka and the Python venv (what `make test` needs)
#   make deps-py       the venv with every package of requirements.lock
#   make lock          re-resolve requirements.txt into requirements.lock (review the diff)
# deps-c, deps-cross, deps-fuzz, deps-analyze, deps-bench: the Debian packages of each role.

# Debian packages of each role.
APT_C := libcmocka-dev
APT_VENV := python3-venv
APT_CROSS := gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm
APT_FUZZ := clang libclang-rt-dev
APT_ANALYZE := cppcheck
APT_BENCH := valgrind

# Installs wait for each other (flock on one file of the machine, whatever BUILDDIR): make -j
# runs two roles' installs at once, and apt-get fails rather than waits on another's lock.
APT_LOCK ?= /tmp/orbillum-apt.lock
APT_GET = SUDO=; [ "$$(id -u)" = 0 ] || SUDO=sudo; \
  flock $(APT_LOCK) $$SUDO env DEBIAN_FRONTEND=noninteractive \
  sh -c 'apt-get update -qq && apt-get install -y -qq "$$@"' apt-get

# apt_need(probe, packages): when the shell probe fails, install the packages (sudo unless root).
define apt_need
	@if ! { $(1); } >/dev/null 2>&1; then echo "installing $(2)"; $(APT_GET) $(2); fi
endef

PROBE_CMOCKA = printf '\#include <stdarg.h>\n\#include <stddef.h>\n\#include <stdint.h>\n\#include <setjmp.h>\n\#include <cmocka.h>\n' | $(CC) -E -x c - >/dev/null
PROBE_CROSS = command -v $(CROSS_PREFIX)gcc && command -v $(QEMU) && \
  echo '\#include <math.h>' | $(CROSS_PREFIX)gcc -E -x c - >/dev/null
PROBE_FUZZ = printf 'int LLVMFuzzerTestOneInput(const unsigned char *d, unsigned long n)\n{ (void)d; (void)n; return 0; }\n' \
  | $(FUZZ_CC) -x c -fsanitize=fuzzer,address,undefined - -o $(BUILDDIR)/.fuzz-probe && rm -f $(BUILDDIR)/.fuzz-probe

.PHONY: deps deps-c deps-py deps-cross deps-fuzz deps-analyze deps-bench lock

deps: deps-c deps-py ## install what the build and tests need (cmocka, a Python venv from requirements.lock)

deps-c: $(BUILDDIR)/.deps-c
$(BUILDDIR)/.deps-c:
	@mkdir -p $(BUILDDIR)
	$(call apt_need,$(PROBE_CMOCKA),$(APT_C))
	@touch $@

deps-cross: $(BUILDDIR)/.deps-cross
$(BUILDDIR)/.deps-cross:
	@mkdir -p $(BUILDDIR)
	$(call apt_need,$(PROBE_CROSS),$(APT_CROSS))
	@touch $@

deps-fuzz: $(BUILDDIR)/.deps-fuzz
$(BUILDDIR)/.deps-fuzz:
	@mkdir -p $(BUILDDIR)
	$(call apt_need,$(PROBE_FUZZ),$(APT_FUZZ))
	@touch $@

deps-analyze: $(BUILDDIR)/.deps-analyze
$(BUILDDIR)/.deps-analyze:
	@mkdir -p $(BUILDDIR)
	$(call apt_need,command -v cppcheck,$(APT_ANALYZE))
	@touch $@

deps-bench: $(BUILDDIR)/.deps-bench
$(BUILDDIR)/.deps-bench:
	@mkdir -p $(BUILDDIR)
	$(call apt_need,command -v valgrind,$(APT_BENCH))
	@touch $@

# The venv: every package at the version of requirements.lock (which must name every
# package of requirements.txt: a package added there without `make lock` fails here).
deps-py: $(VENV)/.deps
$(VENV)/.deps: requirements.lock requirements.txt
	$(call apt_need,[ -x $(PY) ] || python3 -m venv $(VENV),$(APT_VENV))
	@$(PY) -m pip --version >/dev/null 2>&1 || python3 -m venv --clear $(VENV)
	@for p in $$(sed 's/#.*//' requirements.txt); do \
	  grep -qix "$$p" requirements.lock || { echo "deps-py: $$p (requirements.txt) is not in requirements.lock: run make lock"; exit 1; }; \
	done
	$(PY) -m pip install -q --disable-pip-version-check -r requirements.lock
	@touch $@

LOCK_VENV := $(BUILDDIR)/lock-venv
lock: ## re-resolve requirements.txt (its top-level pins; raise one there to upgrade) into requirements.lock; check the wheels, review the diff
	rm -rf $(LOCK_VENV) && python3 -m venv $(LOCK_VENV)
	$(LOCK_VENV)/bin/python -m pip install -q --disable-pip-version-check --upgrade pip
	$(LOCK_VENV)/bin/python -m pip install -q --disable-pip-version-check -r requirements.txt
	{ sed -n '/^#/p' requirements.lock; \
	  $(LOCK_VENV)/bin/python -m pip freeze --all --exclude pip | grep -v '^setuptools==\|^wheel=='; \
	  $(LOCK_VENV)/bin/python -m pip freeze --all | grep '^setuptools==\|^wheel=='; } > $(LOCK_VENV)/requirements.lock
	mv $(LOCK_VENV)/requirements.lock requirements.lock
	@echo "requirements.lock rewritten; check the wheels for each Python it serves, e.g."
	@echo "  pip download --only-binary=:all: --no-deps --python-version 3.13 -d /tmp/w -r requirements.lock"
