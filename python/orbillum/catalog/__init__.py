# SPDX-License-Identifier: MIT
"""orbillum.catalog: the catalogue planner (docs/catalog.md).

Which objects of a TLE catalogue can the observers see, how bright, with what
exposure, at every epoch of a span: ``python -m orbillum.catalog`` (command
line), or from Python::

    from orbillum.catalog import plan, tle, synthetic
    summary, _ = plan.plan(tle.read("cat.3le"), tle.read("inspectors.3le"),
                           "2026-12-01T00:00", "2026-12-08T00:00", 60.0,
                           workers=2, parquet="plan.parquet")

Needs astropy, sgp4, pyarrow, and dask.distributed for workers/scheduler
(requirements.txt); the binding itself needs only numpy.
"""
