"""The numerical core: pure numpy, no drawing, no sentences beyond error messages (the
book's methods step by step are in ``methods``). See docs/api.md and docs/architecture.md.

    from mechanisms import load_preset
    from solvers import solve
    motion = solve(load_preset("analitika-2.1"), numpy.radians([55.0]))
    motion.members[4].omega   # ω₄ in rad/s
"""

from .kinematics import GroupIssue, MemberMotion, Motion, PointMotion, SliderMotion, solve
from .memory import keep_freed_memory
from .structure import Group, Structure, StructureError, decompose, degrees_of_freedom

keep_freed_memory()  # see solvers/memory.py: 2× faster cycles on this VM

__all__ = ["Group", "GroupIssue", "MemberMotion", "Motion", "PointMotion", "SliderMotion",
           "Structure", "StructureError", "decompose", "degrees_of_freedom", "solve"]
