# SPDX-License-Identifier: MIT
# mk/report.mk: `make report` writes docs/report.md and its plots in docs/report/.
# Sections are listed in bake/report.py (SECTIONS); missing ones are skipped with a note.
# REPORT_ARGS: e.g. REPORT_ARGS="--only report_photon" or "--strict".

.PHONY: report
REPORT_ARGS ?=

report: deps-py ## write docs/report.md + docs/report/*.png (every number computed by this run)
	MPLBACKEND=Agg $(PY) -m bake.report --out docs/report.md $(REPORT_ARGS)
