"""geometry stage of cityshade."""
