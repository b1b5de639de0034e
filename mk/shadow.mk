# SPDX-License-Identifier: MIT
# mk/shadow.mk: the mpmath references of the phase, shadow and lunar-phase tests
# (tests/ref/gen_refs.py -> tests/c/ref_phase.h, tests/c/ref_shadow.h).
#
#   make ref-shadow        regenerate both headers (~6 minutes, mpmath at 45+ digits)
#   make check-ref-shadow  regenerate and fail if the committed headers differ
#   make shadow-report     the planar (Montenbruck & Gill) vs exact spherical comparison

.PHONY: ref-shadow check-ref-shadow shadow-report

ref-shadow: deps-py ## regenerate tests/c/ref_phase.h and ref_shadow.h (mpmath, ~6 min)
	$(PY) tests/ref/gen_refs.py

check-ref-shadow: ref-shadow ## regenerate the phase/shadow references and fail on any difference
	git diff --exit-code -- tests/c/ref_phase.h tests/c/ref_shadow.h

shadow-report: deps-py ## planar Montenbruck-Gill vs exact spherical Sun fraction (regenerates refs)
	$(PY) tests/ref/gen_refs.py --only shadow --report

# test_shadow with the limb-darkened disc compiled out (OI_NO_LIMB_DARKENING,
# include/oi_config.h): fraction_ld == fraction, OI_LIMB_DARKENED refused.
NOLD_DIR := $(BUILDDIR)/nold
.PHONY: test-shadow-nold
test-shadow-nold: ## test_shadow built with -DOI_NO_LIMB_DARKENING, both precisions
	@$(MAKE) --no-print-directory BUILDDIR=$(NOLD_DIR) EXTRA_DEFS=-DOI_NO_LIMB_DARKENING \
	  TEST_CFLAGS="$(TEST_CFLAGS) -DOI_NO_LIMB_DARKENING" \
	  $(NOLD_DIR)/tests/double/test_shadow $(NOLD_DIR)/tests/float/test_shadow
	$(NOLD_DIR)/tests/double/test_shadow
	$(NOLD_DIR)/tests/float/test_shadow
TEST_TARGETS += test-shadow-nold
