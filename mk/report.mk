# SPDX-License-Identifier: MIT
# mk/report.mk: `make report` writes docs/report.md and its plots in docs/report/.
# Sections are listed in bake/report.py (SECTIONS); missing ones are skipped with a note.
# REPORT_ARGS: e.g. REPORT_ARGS="--only report_photon" or "--strict".

.PHONY: report
REPORT_ARGS ?=

report: deps-py ## write docs/report.md + docs/report/*.png (every number computed by this run)
	MPLBACKEND=Agg $(PY) -m bake.report --out docs/report.md $(REPORT_ARGS)

.PHONY: golden
golden: $(PLAN) ## re-record tests/golden/*.plan.csv and demo.txt (only for a change meant to move them)
	@for f in tests/golden/*.in.csv; do $(PLAN) --csv $$f > $${f%.in.csv}.plan.csv || [ $$? -eq 1 ]; done
	$(PLAN) > tests/golden/demo.txt
