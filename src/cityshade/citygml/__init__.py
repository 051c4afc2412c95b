"""citygml stage of cityshade."""
