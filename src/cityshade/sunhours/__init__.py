"""Sun-hours over times: ``plan`` (time plan, work units), ``request`` (the typed
:class:`~cityshade.sunhours.request.SunHoursRequest` and its checks), ``accumulate`` (the
untiled run and what both runs share), ``tiled`` (tiled runs and their local driver),
``distributed`` (the Dask executor), ``checkpoint`` (saved state, manifest, their throttles),
``outputs`` (colour map, legend, writers), ``surfaces`` (per-surface samples),
``stretches`` (sunlit stretches) and ``run`` (``run_batch``: the resumable run in a folder)."""
