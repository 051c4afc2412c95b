"""trace stage of cityshade."""
