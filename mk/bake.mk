# SPDX-License-Identifier: MIT
# mk/bake.mk: the earthshine tables (issue 3). Included by the Makefile.
#   make bake          regenerate the committed tables (tables/oi_earth_*.{c,h,json})
#                      byte for byte: the default table and every bake/config/scene_*.json
#   make check-tables  re-bake into a temporary folder and fail on any difference
#   make ref-earthshine regenerate tests/c/ref_earthshine.h (C test vectors)

BAKE_TMP ?= $(BUILDDIR)/check-tables
BAKE_FLAGS ?=

.PHONY: bake check-tables ref-earthshine

bake: deps-py ## regenerate tables/oi_earth_* (default table + scenes), byte for byte
	$(PY) -m bake --all --out tables $(BAKE_FLAGS)

check-tables: deps-py ## re-bake into a temp folder and fail on any difference with tables/
	@rm -rf $(BAKE_TMP) && mkdir -p $(BAKE_TMP)
	$(PY) -m bake --all --out $(BAKE_TMP) $(BAKE_FLAGS)
	@set -e; fail=0; \
	for f in $(BAKE_TMP)/*; do \
	  b=$$(basename $$f); \
	  if ! cmp -s $$f tables/$$b; then echo "check-tables: tables/$$b differs from a fresh bake"; fail=1; fi; \
	done; \
	for f in tables/oi_earth_*; do \
	  b=$$(basename $$f); \
	  [ -e $(BAKE_TMP)/$$b ] || { echo "check-tables: tables/$$b is not produced by the bake"; fail=1; }; \
	done; \
	if [ $$fail = 0 ]; then echo "check-tables: tables/ matches a fresh bake byte for byte"; fi; \
	exit $$fail

ref-earthshine: deps-py ## regenerate tests/c/ref_earthshine.h from the quadrature reference
	$(PY) -m bake.gen_test_vectors
