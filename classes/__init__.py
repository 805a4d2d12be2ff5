"""Classes and their stored checks: a lecturer's class joined by code, every practice check
a student makes stored before its verdict is shown (docs/classes.md). No Streamlit here."""
