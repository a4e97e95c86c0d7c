"""The construction engine: a DAG of drawing steps whose evaluation is the solution."""
