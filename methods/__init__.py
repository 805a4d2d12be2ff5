"""The book's methods written out step by step, for people: the velocity and acceleration
plans, the 12-step compass construction, graphical kinetostatics and the reduced mechanism's
lever, Willis' equation stage by stage, and the complex-number (vector-loop) method. Each
takes the exact solution from ``solvers`` and lays out the construction as data, sentences
and LaTeX; pages and figures show it."""
