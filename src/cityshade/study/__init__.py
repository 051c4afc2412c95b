"""Shadow studies (docs/DESIGN.md §22): the shadows of two city states at fixed times on fixed
days, as sheets for a planning application (``cityshade study``)."""
from cityshade.study.request import StudyRequest, StudyTimes
from cityshade.study.run import StudyResult, run_study

__all__ = ["StudyRequest", "StudyResult", "StudyTimes", "run_study"]
