"""The book's tasks 2.1 and 2.2 against solutions written here independently of the solver."""

import math

import numpy as np
import pytest

from mechanisms import load_preset
from solvers import solve


def fourbar_2_1(phi2, omega2=-10.0):
    """Task 2.1's loop OACD by the law of cosines and numpy's linear solver."""
    o, d = 0j, complex(-0.43, 0.34)
    r2, r3, r4 = 0.3, 0.6, 0.25
    a = o + r2 * np.exp(1j * phi2)
    ad = d - a
    # angle at A between AD and AC from the law of cosines; the book's assembly: C to the left of AD
    gamma = math.acos((r3**2 + abs(ad) ** 2 - r4**2) / (2 * r3 * abs(ad)))
    phi3 = np.angle(ad) + gamma
    c = a + r3 * np.exp(1j * phi3)
    phi4 = np.angle(c - d)
    e2, e3, e4 = (1j * np.exp(1j * p) for p in (phi2, phi3, phi4))
    m = np.array([[r3 * e3.real, -r4 * e4.real], [r3 * e3.imag, -r4 * e4.imag]])
    w3, w4 = np.linalg.solve(m, [-(r2 * omega2 * e2).real, -(r2 * omega2 * e2).imag])
    rhs = (r2 * omega2**2 * np.exp(1j * phi2) + r3 * w3**2 * np.exp(1j * phi3)
           - r4 * w4**2 * np.exp(1j * phi4))
    eps3, eps4 = np.linalg.solve(m, [rhs.real, rhs.imag])
    return dict(phi3=phi3, phi4=phi4, w3=w3, w4=w4, eps3=eps3, eps4=eps4, a=a)


def test_task_2_1_fourbar_matches_independent_solution():
    motion = solve(load_preset("analitika-2.1"))
    ref = fourbar_2_1(math.radians(55.0))
    m = motion.members
    assert math.degrees(m[3].angle[0]) % 360 == pytest.approx(math.degrees(ref["phi3"]) % 360, abs=1e-9)
    assert math.degrees(m[4].angle[0]) % 360 == pytest.approx(math.degrees(ref["phi4"]) % 360, abs=1e-9)
    assert m[3].omega[0] == pytest.approx(ref["w3"], rel=1e-10)
    assert m[4].omega[0] == pytest.approx(ref["w4"], rel=1e-10)
    assert m[3].epsilon[0] == pytest.approx(ref["eps3"], rel=1e-10)
    assert m[4].epsilon[0] == pytest.approx(ref["eps4"], rel=1e-10)


def test_task_2_1_exact_values_not_the_books_slip():
    """The values the issue lists as exact (the book prints ω₄ = 8.148 after a digit swap)."""
    motion = solve(load_preset("analitika-2.1"))
    m = motion.members
    assert math.degrees(m[3].angle[0]) % 360 == pytest.approx(194.95, abs=0.005)
    assert math.degrees(m[4].angle[0]) % 360 == pytest.approx(275.13, abs=0.005)
    assert m[3].omega[0] == pytest.approx(-3.271, abs=5e-4)
    assert m[4].omega[0] == pytest.approx(7.837, abs=5e-4)
    assert m[3].epsilon[0] == pytest.approx(-62.91, abs=5e-3)
    assert m[4].epsilon[0] == pytest.approx(-77.78, abs=5e-3)
    assert abs(m[4].omega[0] - 8.148) > 0.3


def test_task_2_1_point_m_by_the_second_loop():
    """Loop OABEO: r₅ and φ₅ from E − B, then ṙ₅, ω₅ and r̈₅, ε₅ from equations B and C."""
    motion = solve(load_preset("analitika-2.1"))
    ref = fourbar_2_1(math.radians(55.0))
    w2, w3, e3 = -10.0, ref["w3"], ref["eps3"]
    b = ref["a"] + 0.45 * np.exp(1j * ref["phi3"])
    e = complex(0.0, -0.18)
    r5, phi5 = abs(e - b), np.angle(e - b)
    u5, n5 = np.exp(1j * phi5), 1j * np.exp(1j * phi5)
    vb = 0.3 * w2 * 1j * np.exp(1j * math.radians(55)) + 0.45 * w3 * 1j * np.exp(1j * ref["phi3"])
    m = np.array([[u5.real, r5 * n5.real], [u5.imag, r5 * n5.imag]])
    r5dot, w5 = np.linalg.solve(m, [-vb.real, -vb.imag])
    ab = (-0.3 * w2**2 * np.exp(1j * math.radians(55)) + 0.45 * e3 * 1j * np.exp(1j * ref["phi3"])
          - 0.45 * w3**2 * np.exp(1j * ref["phi3"]))
    rest = ab + 2 * r5dot * w5 * n5 - r5 * w5**2 * u5
    r5ddot, e5 = np.linalg.solve(m, [-rest.real, -rest.imag])
    zm = b + 0.205 * u5
    vm = vb + 0.205 * w5 * n5
    am = ab + 0.205 * e5 * n5 - 0.205 * w5**2 * u5
    p = motion.points["M"]
    assert complex(p.z[0]) == pytest.approx(zm, abs=1e-12)
    assert complex(p.v[0]) == pytest.approx(vm, abs=1e-10)
    assert complex(p.a[0]) == pytest.approx(am, abs=1e-9)
    slider = motion.sliders["5-6"]
    assert slider.s[0] == pytest.approx(r5, abs=1e-12)
    assert slider.v[0] == pytest.approx(r5dot, rel=1e-10)
    assert slider.a[0] == pytest.approx(r5ddot, rel=1e-10)
    assert complex(slider.coriolis[0]) == pytest.approx(2 * r5dot * w5 * n5, rel=1e-10)


def task_2_2_positions(ry):
    """Task 2.2 by Newton's method on both loops, written here (not the solver's closed form)."""
    a, b0 = 1j * ry, 1j * ry + 0.26 * np.exp(1j * math.radians(50))
    d, f = complex(0.69, 0), complex(0.27, 0.585)

    def newton(fun, x):
        for _ in range(50):
            r = fun(x)
            jac = np.empty((2, 2))
            for k in range(2):
                dx = np.zeros(2)
                dx[k] = 1e-7
                col = (fun(x + dx) - r) / 1e-7
                jac[:, k] = col
            x = x - np.linalg.solve(jac, r)
        return x

    def loop1(x):
        r3, phi3 = x
        z = b0 + r3 * np.exp(1j * phi3) - d - 0.27 * np.exp(1j * (phi3 + math.radians(85)))
        return np.array([z.real, z.imag])

    r3, phi3 = newton(loop1, np.array([0.6, math.radians(350)]))

    def loop2(x):
        r3e, phi6 = x
        z = b0 + r3e * np.exp(1j * phi3) - f - 0.4 * np.exp(1j * phi6)
        return np.array([z.real, z.imag])

    r3e, phi6 = newton(loop2, np.array([0.39, math.radians(314)]))
    return dict(a=a, r3=r3, phi3=phi3, r3e=r3e, phi6=phi6, m=f + 0.2 * np.exp(1j * phi6))


def test_task_2_2_positions_and_rates_match_independent_newton():
    scene = load_preset("analitika-2.2")
    ry, v, h = 0.17, 3.0, 1e-6
    motion = solve(scene, [ry])
    ref, ahead, back = (task_2_2_positions(x) for x in (ry, ry + h, ry - h))
    m, s = motion.members, motion.sliders
    assert np.angle(np.exp(1j * (m[3].angle[0] - ref["phi3"]))) == pytest.approx(0, abs=1e-9)
    assert np.angle(np.exp(1j * (m[6].angle[0] - ref["phi6"]))) == pytest.approx(0, abs=1e-9)
    assert s["3-4"].s[0] == pytest.approx(ref["r3"], abs=1e-9)
    assert s["3-5"].s[0] == pytest.approx(ref["r3e"], abs=1e-9)
    assert complex(motion.points["M"].z[0]) == pytest.approx(ref["m"], abs=1e-9)
    rate = lambda key: v * (ahead[key] - back[key]) / (2 * h)  # noqa: E731
    assert m[3].omega[0] == pytest.approx(rate("phi3"), rel=1e-5)
    assert m[6].omega[0] == pytest.approx(rate("phi6"), rel=1e-5)
    assert s["3-4"].v[0] == pytest.approx(rate("r3"), rel=1e-5)
    assert complex(motion.points["M"].v[0]) == pytest.approx(rate("m"), rel=1e-5)


def test_task_2_2_accelerations_match_second_differences_of_the_independent_solution():
    """ε₃ and r̈₃ (where the book's printed values differ) from the Newton positions alone."""
    scene = load_preset("analitika-2.2")
    ry, v, h = 0.17, 3.0, 1e-4
    motion = solve(scene, [ry])
    back, mid, ahead = (task_2_2_positions(x) for x in (ry - h, ry, ry + h))
    second = lambda key: v * v * (ahead[key] - 2 * mid[key] + back[key]) / h**2  # noqa: E731
    assert motion.members[3].epsilon[0] == pytest.approx(second("phi3"), rel=1e-4)
    assert motion.sliders["3-4"].a[0] == pytest.approx(second("r3"), rel=1e-4)
    assert motion.members[6].epsilon[0] == pytest.approx(second("phi6"), rel=1e-4)
