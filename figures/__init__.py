"""Plotly figure builders: pure functions from solver results to figures (no solving here)."""
