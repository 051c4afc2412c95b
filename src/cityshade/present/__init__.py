"""What a person looks at: maps with context (scale bar, north arrow, CRS, colour bar), reports
that open in any browser, and the per-surface answers as GIS layers (docs/DESIGN.md §19).

``maps`` (matplotlib, the ``[plot]`` extra), ``html`` (markdown-it-py), ``gis`` (pyogrio and
shapely): each imported by the writers of ``render``, ``batch``, ``compare`` and ``evaluate``
only when they write.
"""
