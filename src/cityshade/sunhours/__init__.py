"""Sun-hours over times: the time plan, accumulation, per-surface results, sunlit stretches,
tiled and Dask runs, checkpoints and the batch's outputs."""
