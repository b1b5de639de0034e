# SPDX-License-Identifier: MIT
# mk/atm.mk: the atmosphere table (issue 4). Included by the Makefile.
#   make bake-atm          regenerate tables/oi_atm_table.{c,h,json} and tests/c/ref_atmosphere.h
#   make check-tables-atm  re-bake into a temporary folder and fail on any difference
# `make bake` and `make check-tables` run these too.

ATM_TMP ?= $(BUILDDIR)/check-tables-atm

.PHONY: bake-atm check-tables-atm

bake-atm: deps-py ## regenerate the atmosphere table (tables/oi_atm_table.*) and its C test vectors
	$(PY) -m bake.atm_table --out tables --vectors tests/c/ref_atmosphere.h

check-tables-atm: deps-py ## re-bake the atmosphere table and fail on any difference
	@rm -rf $(ATM_TMP) && mkdir -p $(ATM_TMP)
	$(PY) -m bake.atm_table --out $(ATM_TMP) --vectors $(ATM_TMP)/ref_atmosphere.h
	@set -e; fail=0; \
	for f in oi_atm_table.c oi_atm_table.h oi_atm_table.json; do \
	  cmp -s $(ATM_TMP)/$$f tables/$$f || { echo "check-tables-atm: tables/$$f differs from a fresh bake"; fail=1; }; \
	done; \
	cmp -s $(ATM_TMP)/ref_atmosphere.h tests/c/ref_atmosphere.h || { echo "check-tables-atm: tests/c/ref_atmosphere.h differs"; fail=1; }; \
	if [ $$fail = 0 ]; then echo "check-tables-atm: atmosphere table matches a fresh bake byte for byte"; fi; \
	exit $$fail

bake: bake-atm
check-tables: check-tables-atm
