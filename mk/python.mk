# SPDX-License-Identifier: MIT
# mk/python.mk: the shared library, the Python binding, real-use examples.
#
#   make shared        build/liborbillum.so (double) from src/<layer>/*.c tables/*.c, -fPIC, strict flags
#   make binding       install the binding (python/) into the venv (pip install ./python)
#   make pass-example  a shipped TLE case -> planner CSV -> pass plan -> plot + rendered view,
#                      in build/pass-example/ (PASS_CASE=geo-inspector-eclipse by default)
#   make gallery       pass plots and views of the three shipped cases in build/gallery/out/
#   make gallery-docs  the same, refreshing the committed docs/gallery/
#   make light-curve   a tumbling box-wing over a shipped pass beside the sphere: its V magnitude
#                      against time, plotted into build/light-curve/ (LC_CASE=leo-leo-pass)

SHARED_LIB := $(BUILDDIR)/liborbillum.so
RT_HDR := $(wildcard include/*.h include/*/*.h src/*.h src/*/*.h tables/*.h)
PY_BINDING_SRC := python/pyproject.toml python/setup.py $(wildcard python/orbillum/*.py python/orbillum/catalog/*.py python/orbillum/catalog/data/*)
PASS_CASE ?= geo-inspector-eclipse
PASS_DIR := $(BUILDDIR)/pass-example
LC_CASE ?= leo-leo-pass
LC_DIR := $(BUILDDIR)/light-curve

.PHONY: shared binding pass-example gallery gallery-docs light-curve

shared: $(SHARED_LIB) ## build build/liborbillum.so (double precision, for the Python binding)

# The runtime's position-independent objects, one per source (make -j builds them side by side),
# shared by build/liborbillum.so and build/libori_test.so.
OBJ_pic := $(patsubst %.c,$(BUILDDIR)/obj/pic/%.o,$(RT_SRC))
$(BUILDDIR)/obj/pic/%.o: %.c
	@mkdir -p $(dir $@)
	$(CC) $(RT_CFLAGS) -fPIC $(EXTRA_DEFS) -MMD -MP -c $< -o $@
-include $(OBJ_pic:.o=.d)

$(SHARED_LIB): $(OBJ_pic)
	@mkdir -p $(dir $@)
	$(CC) $(RT_CFLAGS) -fPIC -shared $(OBJ_pic) -lm -o $@

binding: $(VENV)/.orbillum-binding ## pip install ./python into the venv (builds its own liborbillum.so)
$(VENV)/.orbillum-binding: $(PY_BINDING_SRC) $(RT_SRC) $(RT_HDR) | deps-py
	$(PY) -m pip install -q --disable-pip-version-check --no-build-isolation --no-deps ./python
	@rm -rf python/build python/*.egg-info
	@touch $@

# The Python tests exercise the installed binding.
test-py-0 test-py-1: binding

pass-example: all binding ## shipped TLE case -> pass plan CSV + plot + rendered view (build/pass-example/)
	@mkdir -p $(PASS_DIR)
	$(PY) -m examples.scenarios --case $(PASS_CASE) -o $(PASS_DIR)/$(PASS_CASE).csv
	$(PLAN) --csv $(PASS_DIR)/$(PASS_CASE).csv > $(PASS_DIR)/$(PASS_CASE)-plan.csv || [ $$? -eq 1 ]
	$(PY) -m examples.render.pass_plot $(PASS_DIR)/$(PASS_CASE).csv $(PASS_DIR)/$(PASS_CASE)-plan.csv \
	  -o $(PASS_DIR)/$(PASS_CASE)-pass.png
	$(PY) -m examples.render.view $(PASS_DIR)/$(PASS_CASE).csv -o $(PASS_DIR)/$(PASS_CASE)-view.png
	@echo "pass plan: $(PASS_DIR)/$(PASS_CASE)-plan.csv"
	@echo "plot:      $(PASS_DIR)/$(PASS_CASE)-pass.png"
	@echo "view:      $(PASS_DIR)/$(PASS_CASE)-view.png"

gallery: all binding ## pass plots and views of the shipped cases in build/gallery/out/ (the tree stays clean)
	$(PY) -m examples.render.gallery --plan $(PLAN) --out $(BUILDDIR)/gallery/out --work $(BUILDDIR)/gallery

gallery-docs: all binding ## the gallery, refreshing the committed docs/gallery/
	$(PY) -m examples.render.gallery --plan $(PLAN) --out docs/gallery --work $(BUILDDIR)/gallery

light-curve: all binding ## tumbling box-wing vs sphere over a shipped pass: V against time (build/light-curve/)
	$(PY) -m examples.render.light_curve --case $(LC_CASE) --plan $(PLAN) --out $(LC_DIR)
	@echo "light curve: $(LC_DIR)/$(LC_CASE)-light-curve.png (data: $(LC_CASE)-light-curve.csv)"

# ---- the thin test binding's shared library (tests/python/_oi_ctypes.py):
# the double-precision runtime plus a struct-size probe. Not the public
# binding's build/liborbillum.so.
ORI_TEST_SO := $(BUILDDIR)/libori_test.so
$(ORI_TEST_SO): $(OBJ_pic) tests/stability/ori_test_abi.c $(RT_HDR)
	@mkdir -p $(dir $@)
	$(CC) $(RT_CFLAGS) -fPIC -shared $(OBJ_pic) tests/stability/ori_test_abi.c -lm -o $@

ori-test-so: $(ORI_TEST_SO)
test-py-0 test-py-1: $(ORI_TEST_SO)
.PHONY: ori-test-so