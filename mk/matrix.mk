# SPDX-License-Identifier: MIT
# mk/matrix.mk: every compile-time option set, in both precisions, with the C unit tests.
#
#   make test-options   for each variant <precision>-<option set>: build the library and every
#                       tests/c/test_*.c into build/variants/<variant>/ and run them
#   make variant-<v>    the same for one variant (e.g. make variant-float-no_moon)
#
# A test that does not apply under an option says so and exits 0 ("skip test_moon: ...");
# the option sets measured by `make size` are part of the matrix.

# Compile-time option sets (full = the defaults); a fragment included before (mk/size.mk) may
# define its own or more, each OPTSET_<name> with its name in SIZE_OPTSETS.
OPTSET_full ?=
OPTSET_no_moon ?= -DOI_NO_MOON
OPTSET_no_exposure ?= -DOI_NO_EXPOSURE
OPTSET_no_atmosphere ?= -DOI_NO_ATMOSPHERE
OPTSET_no_earth_table ?= -DOI_NO_EARTH_TABLE
OPTSET_no_earth_angular ?= -DOI_NO_EARTH_ANGULAR
OPTSET_no_limb_darkening ?= -DOI_NO_LIMB_DARKENING
OPTSET_no_sky ?= -DOI_NO_SKY
OPTSET_no_facets ?= -DOI_NO_FACETS
OPTSET_no_oblate ?= -DOI_NO_OBLATE
OPTSET_no_albedo_models ?= -DOI_NO_ALBEDO_MODELS
OPTSET_no_skylight ?= -DOI_NO_SKYLIGHT
OPTSET_no_total_band ?= -DOI_NO_TOTAL_BAND
OPTSET_sun_only ?= -DOI_NO_MOON -DOI_NO_EXPOSURE -DOI_NO_ATMOSPHERE -DOI_NO_EARTH_TABLE -DOI_NO_SKY \
  -DOI_NO_FACETS -DOI_NO_OBLATE -DOI_NO_SKYLIGHT
OPTSET_sun_uniform ?= $(OPTSET_sun_only) -DOI_NO_LIMB_DARKENING
OPTSETS := full no_moon no_exposure no_atmosphere no_earth_table no_earth_angular no_limb_darkening \
           no_sky no_facets no_oblate no_albedo_models no_skylight sun_only sun_uniform \
           no_total_band
# every option set `make size` measures is tested too (mk/target.mk, mk/size.mk)
OPTSETS += $(filter-out $(OPTSETS),$(CROSS_OPTSETS) $(SIZE_OPTSETS))
$(foreach s,$(OPTSETS),$(if $(filter undefined,$(origin OPTSET_$(s))),$(error option set $(s) has no OPTSET_$(s))))

PRECISIONS := double float
VARIANTS := $(foreach p,$(PRECISIONS),$(foreach s,$(OPTSETS),$(p)-$(s)))
VARIANT_DIR := $(BUILDDIR)/variants

var_prec = $(word 1,$(subst -, ,$(1)))
var_set = $(word 2,$(subst -, ,$(1)))
var_defs = $(DEF_$(call var_prec,$(1))) $(OPTSET_$(call var_set,$(1)))

# run_variant_tests(programs): each program's output goes to <program>.log; one line per
# program, "ok|FAIL <variant> <test>" (with its skip notes), the whole log of a failing one.
define run_variant_tests
	@set -e; for t in $(1); do \
	  v=$$(basename $$(dirname $$(dirname $$t))); \
	  if $$t > $$t.log 2>&1; then \
	    echo "ok   $$v $$(basename $$t)"; grep '^skip' $$t.log | sed 's/^/     /' || true; \
	  else cat $$t.log; echo "FAIL $$v $$(basename $$t) (log: $$t.log)"; exit 1; fi; \
	done
endef

# $(1) = variant: objects, library and test programs under build/variants/$(1)/
define VARIANT_RULES
$(VARIANT_DIR)/$(1)/obj/%.o: %.c
	@mkdir -p $$(dir $$@)
	$$(CC) $$(RT_CFLAGS) $(call var_defs,$(1)) -MMD -MP -c $$< -o $$@

$(VARIANT_DIR)/$(1)/liborbillum.a: $(patsubst %.c,$(VARIANT_DIR)/$(1)/obj/%.o,$(RT_SRC))
	rm -f $$@ && $$(AR) rcs $$@ $$^

$(VARIANT_DIR)/$(1)/tests/%: tests/c/%.c $(VARIANT_DIR)/$(1)/liborbillum.a | deps-c
	@mkdir -p $$(dir $$@)
	$$(CC) $$(TEST_CFLAGS) $(call var_defs,$(1)) $$< $(VARIANT_DIR)/$(1)/liborbillum.a -lcmocka -lm -o $$@

.PHONY: variant-$(1)
variant-$(1): $(patsubst tests/c/%.c,$(VARIANT_DIR)/$(1)/tests/%,$(CTEST_SRC))
	$$(call run_variant_tests,$$^)

-include $(patsubst %.c,$(VARIANT_DIR)/$(1)/obj/%.d,$(RT_SRC))
endef
$(foreach v,$(VARIANTS),$(eval $(call VARIANT_RULES,$(v))))

.PHONY: test-options
test-options: $(addprefix variant-,$(VARIANTS)) ## every C unit test under every compile-time option set, both precisions
	@echo "test-options: $(words $(VARIANTS)) variants passed"

# test_shadow with the limb-darkened disc compiled out, both precisions (part of `make test`)
.PHONY: test-shadow-nold
test-shadow-nold: $(foreach p,$(PRECISIONS),$(VARIANT_DIR)/$(p)-no_limb_darkening/tests/test_shadow) ## test_shadow built with -DOI_NO_LIMB_DARKENING, both precisions
	$(call run_variant_tests,$^)
TEST_TARGETS += test-shadow-nold
