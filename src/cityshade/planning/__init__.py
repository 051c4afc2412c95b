"""Planning questions before and after a change: ``compare`` (two states of a city on the same
receivers), the published rules (:mod:`.rules`, ``rules_data/``), the report, and the one call
that runs them all (:func:`cityshade.planning.run.run_compare` on a
:class:`cityshade.planning.run.CompareRequest`)."""
