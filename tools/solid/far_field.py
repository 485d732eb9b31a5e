"""The inflated far field of a long closed-end St-VK tube (src/fe/README.md eq. 8), used to
place the probe and the plate just clear of the inflated wall before the solve."""
import numpy as np
from scipy.optimize import fsolve


def stvk_stretches(p_over_E, h0_over_d0, nu):
    """Hoop, axial and thickness stretches of the membrane far field (plane stress St-VK)."""
    P = p_over_E / h0_over_d0

    def equations(stretch):
        l1, l2 = stretch
        e1, e2 = (l1 ** 2 - 1) / 2, (l2 ** 2 - 1) / 2
        s1, s2 = (e1 + nu * e2) / (1 - nu ** 2), (e2 + nu * e1) / (1 - nu ** 2)
        return [s1 - P * l2 / 2, s2 - P * l1 ** 2 / (4 * l2)]
    l1, l2 = fsolve(equations, [1.0 + P / 2, 1.0 + P / 8], xtol=1e-13)
    e1, e2 = (l1 ** 2 - 1) / 2, (l2 ** 2 - 1) / 2
    return l1, l2, np.sqrt(1 - 2 * nu / (1 - nu) * (e1 + e2))
