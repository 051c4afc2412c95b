"""cli stage of cityshade."""
