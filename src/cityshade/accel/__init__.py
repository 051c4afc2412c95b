"""accel stage of cityshade."""
