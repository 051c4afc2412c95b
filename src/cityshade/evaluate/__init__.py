"""``cityshade evaluate``: error against run time of every shadow technique, and the stress set.

One module per job: :mod:`~cityshade.evaluate.run` (technique lists, the frame loop on the
pipeline), :mod:`~cityshade.evaluate.metrics` (error against the exact reference),
:mod:`~cityshade.evaluate.report` (CSV, Markdown, difference images),
:mod:`~cityshade.evaluate.plot` (the error-against-time plot) and
:mod:`~cityshade.evaluate.stress` (the stress set). Nothing outside this package but the CLI
imports from it.
"""
from __future__ import annotations

from cityshade.evaluate.metrics import (LIT_THRESHOLD, Reference, compare, finite_check,
                                        make_reference, nearest_feature, pareto_front)
from cityshade.evaluate.plot import error_time_plot
from cityshade.evaluate.report import (CSV_COLUMNS, diff_image, report_markdown, summary,
                                       write_csv, write_report)
from cityshade.evaluate.run import (Case, EvaluateSettings, Evaluation, FrameSetup,
                                    evaluate_frame, expand_techniques, load_or_build_scene,
                                    map_family, parse_suns, run_evaluation, sun_label,
                                    suns_of_day, uses_map, view_camera)

__all__ = ["LIT_THRESHOLD", "Reference", "compare", "finite_check", "make_reference",
           "nearest_feature", "pareto_front", "error_time_plot", "CSV_COLUMNS", "diff_image",
           "report_markdown", "summary", "write_csv", "write_report", "Case",
           "EvaluateSettings", "Evaluation", "FrameSetup", "evaluate_frame",
           "expand_techniques", "load_or_build_scene", "map_family", "parse_suns",
           "run_evaluation", "sun_label", "suns_of_day", "uses_map", "view_camera"]
