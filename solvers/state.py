"""The motion of one rigid member over the cycle, in complex numbers.

A member is kept as the motion of one reference point of it (local coordinate ``ref``,
world position ``z``, velocity ``v``, acceleration ``a``) plus its rotation
``rot = e^{iθ}``, ω and ε. Any other point ``c`` of the member then follows the
rigid-body rules the plans use:
    z_c = z + (c − ref)·rot,  v_c = v + iω·(c − ref)·rot,  a_c = a + (iε − ω²)·(c − ref)·rot.
The solver keeps ``rot`` (a unit complex number) and derives θ only when asked:
trigonometric functions cost more than the rest of a dyad's arithmetic.
Arrays run over the cycle; constants (the frame, a constant ω₂) stay scalars and broadcast.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np


def unit(angle) -> np.ndarray:
    """e^{i·angle}, a little faster than ``np.exp(1j * angle)`` for real arrays."""
    out = np.empty(np.shape(angle), dtype=complex)
    np.cos(angle, out=out.real)
    np.sin(angle, out=out.imag)
    return out


def cplx(re, im) -> np.ndarray:
    """A complex array from its real and imaginary parts, without complex arithmetic."""
    same = isinstance(re, np.ndarray) and isinstance(im, np.ndarray) and re.shape == im.shape
    out = np.empty(re.shape if same else np.broadcast_shapes(np.shape(re), np.shape(im)), dtype=complex)
    out.real = re
    out.imag = im
    return out


def value_at(x, index: int):
    """Position ``index`` of an array over the cycle (a constant, as the frame's, as it is)."""
    return np.asarray(x).reshape(-1)[index] if np.ndim(x) else x


@dataclass(slots=True)
class Body:
    rot: np.ndarray | complex
    z: np.ndarray | complex = 0j
    ref: complex = 0j
    omega: np.ndarray | float | None = None
    v: np.ndarray | complex | None = None
    epsilon: np.ndarray | float | None = None
    a: np.ndarray | complex | None = None
    angle: np.ndarray | float | None = None  # θ in rad, derived from ``rot`` when not given

    @classmethod
    def frame(cls) -> Body:
        return cls(1 + 0j, 0j, 0j, 0.0, 0j, 0.0, 0j, 0.0)

    @property
    def theta(self):
        if self.angle is None:
            self.angle = np.angle(self.rot)
        return self.angle

    def _at_ref(self, local) -> bool:
        return not isinstance(local, np.ndarray) and local == self.ref

    def arm(self, local: complex):
        """(c − ref)·rot: the world vector from the reference point to point ``c``."""
        return (local - self.ref) * self.rot

    # ``local`` may also be an array: a coincident point that moves along the member
    def position(self, local: complex):
        return self.z if self._at_ref(local) else self.z + self.arm(local)

    def velocity(self, local: complex):
        return self.v if self._at_ref(local) else self._velocity(self.arm(local))

    def acceleration(self, local: complex):
        return self.a if self._at_ref(local) else self._acceleration(self.arm(local))

    def _velocity(self, arm):
        return self.v + 1j * self.omega * arm

    def _acceleration(self, arm):
        return self.a + (1j * self.epsilon - self.omega * self.omega) * arm

    def point(self, local: complex, order: int) -> tuple:
        """Position, velocity and acceleration of point ``local`` up to ``order`` (None
        beyond), its arm computed once for all three."""
        if self._at_ref(local):
            return self.z, self.v if order >= 1 else None, self.a if order >= 2 else None
        arm = self.arm(local)
        return (self.z + arm, self._velocity(arm) if order >= 1 else None,
                self._acceleration(arm) if order >= 2 else None)
