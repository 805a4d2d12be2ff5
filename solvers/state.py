"""The motion of one rigid member over the cycle, in complex numbers.

A member's frame has its origin at the member's first point; a point with local
coordinate ``c`` (complex) is at ``z0 + c·e^{iθ}``. Derivatives follow the rigid-body
rules the plans use: v = v0 + iω·c·e^{iθ}, a = a0 + (iε − ω²)·c·e^{iθ}.
Arrays run over the cycle; the frame uses plain zeros, which broadcast.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


@dataclass
class Body:
    theta: np.ndarray | float
    rot: np.ndarray | complex
    z0: np.ndarray | complex
    omega: np.ndarray | float | None = None
    v0: np.ndarray | complex | None = None
    epsilon: np.ndarray | float | None = None
    a0: np.ndarray | complex | None = None

    @classmethod
    def frame(cls) -> Body:
        return cls(0.0, 1 + 0j, 0j, 0.0, 0j, 0.0, 0j)

    def position(self, local: complex):
        return self.z0 + local * self.rot

    def velocity(self, local: complex):
        return self.v0 + 1j * self.omega * local * self.rot

    def acceleration(self, local: complex):
        return self.a0 + (1j * self.epsilon - self.omega * self.omega) * (local * self.rot)
