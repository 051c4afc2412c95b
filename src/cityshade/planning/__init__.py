"""Planning questions before and after a change: ``compare``, the published rules
(:mod:`.rules`, ``rules_data/``) and the report."""
