#!/usr/bin/env python3
"""The bending length a Peirce cantilever tester (ASTM D1388) reads on a fabric with fibre
friction in bending (KES 2HB).

Model (docs/reference.md, "Fibre friction in bending"; costs/fv_bending_friction.h): on monotone
loading the bending moment per unit width is M = D kappa + H sgn(kappa), with D (N*m) the bending
rigidity and H = 2HB/2 the friction moment (N; H = 2HB[gf*cm/cm]/2 * 9.80665e-3). A strip of
weight per unit area w = rho*g (N/m^2) overhangs a horizontal platform by l (m), clamped at s = 0.
With arc length s, slope theta(s) below the horizontal and moment M(s):

    theta' = max(M - H, 0) / D,    M' = -w (l - s) cos(theta),    theta(0) = 0,    M(l) = 0,

solved by shooting on M(0) (RK4; where M < H the strip stays straight, solved exactly there). The
tester pushes the strip out until the chord from the platform edge to the tip makes 41.5 deg with
the horizontal and reads c = l/2. Nondimensional: c0 = (D/w)^(1/3) (the elastic bending length),
eta = H/(w c0^2); the overhang l* at 41.5 deg is found by bisection over l, and the reading is
c_read/c0 = l*/(2 c0), a function of eta alone. An elastic interpretation infers
B_app = w c_read^3 (reported in gf*cm^2/cm; B = D / 9.80665e-5), B_app/B = (c_read/c0)^3.

Prints (a) c_read/c0 against eta, (b) the cotton shirting of configs/fv/drape_tester_cotton_30.yaml
(W 12 mg/cm^2, B_warp 0.12, B_weft 0.08 gf*cm^2/cm) over 2HB, and Matsudaira et al.'s cotton broad
and polyester faille (W 12 mg/cm^2 assumed). Every l* is computed with N and 2N steps; the largest
relative difference is printed (the step-halving check).

Run:  python3 tools/peirce_friction.py [--steps N] [--eta 0,0.1,...] [--2HB 0,0.05,...]
Standard library only; about 20 s on one core (every overhang solved at N and 2N steps).
"""
import argparse
import math

G = 9.80665                   # m/s^2
GF_CM = 9.80665e-3            # 1 gf*cm/cm = 9.80665e-3 N (moment per unit width)
GF_CM2 = 9.80665e-5           # 1 gf*cm^2/cm = 9.80665e-5 N*m (bending rigidity per unit width)
CHORD = math.radians(41.5)    # the tester's chord angle


def rhs(s, y, lam, eta):
    """Bending region (m > eta): y = (theta, m, x, z), z downward, all over c0."""
    theta, m = y[0], y[1]
    c, sn = math.cos(theta), math.sin(theta)
    return (m - eta, -(lam - s) * c, c, sn)


def rk4_step(s, y, h, lam, eta):
    k1 = rhs(s, y, lam, eta)
    k2 = rhs(s + h / 2, [a + h / 2 * b for a, b in zip(y, k1)], lam, eta)
    k3 = rhs(s + h / 2, [a + h / 2 * b for a, b in zip(y, k2)], lam, eta)
    k4 = rhs(s + h, [a + h * b for a, b in zip(y, k3)], lam, eta)
    return [a + h / 6 * (p + 2 * q + 2 * r + t) for a, p, q, r, t in zip(y, k1, k2, k3, k4)]


def straight_tip(s, y, lam, eta):
    """From s (where m = eta) to the tip the strip is straight at theta: m(lam), tip (x, z)."""
    theta, m, x, z = y
    rest = lam - s
    return m - 0.5 * rest * rest * math.cos(theta), x + rest * math.cos(theta), z + rest * math.sin(theta)


def illinois(f, lo, hi, flo, fhi, tol):
    """A root of f in [lo, hi] (f(lo) < 0 < f(hi)) by false position, Illinois variant.
    Returns (root, whatever f returns at it)."""
    side, out = 0, None
    for _ in range(200):
        mid = (lo * fhi - hi * flo) / (fhi - flo)
        out = f(mid)
        if out[0] == 0.0 or hi - lo < tol:
            break
        if out[0] > 0:
            hi, fhi = mid, out[0]
            flo, side = (flo / 2 if side == -1 else flo), -1
        else:
            lo, flo = mid, out[0]
            fhi, side = (fhi / 2 if side == 1 else fhi), 1
        if min(abs(flo), abs(fhi)) < 1e-15:
            break
    return mid, out


def locate_event(s, y, h, lam, eta):
    """The step d in (0, h] from s at which the RK4 step brings m down to eta."""
    def g(d):
        return (eta - rk4_step(s, y, d, lam, eta)[1],)
    d, _ = illinois(g, 0.0, h, eta - y[1], g(h)[0], 1e-15 * h)
    return d


def shoot(m0, lam, eta, steps):
    """Integrate from the clamp with m(0) = m0; return m(lam) and the tip (x, z)."""
    y = [0.0, m0, 0.0, 0.0]
    if m0 <= eta:
        return straight_tip(0.0, y, lam, eta)
    h = lam / steps
    for i in range(steps):
        s = i * h
        nxt = rk4_step(s, y, h, lam, eta)
        if nxt[1] <= eta:
            d = locate_event(s, y, h, lam, eta)
            return straight_tip(s + d, rk4_step(s, y, d, lam, eta), lam, eta)
        y = nxt
    return y[1], y[2], y[3]


def solve_cantilever(lam, eta, steps):
    """m(0) with m(lam) = 0, on [eta, lam^2/2] (m decreases along the strip, m(0) <= lam^2/2);
    returns the tip (x, z)."""
    lo, hi = eta, 0.5 * lam * lam
    if hi <= eta:
        return lam, 0.0                       # friction holds the whole strip straight
    flo, fhi = shoot(lo, lam, eta, steps)[0], shoot(hi, lam, eta, steps)[0]
    _, (f, x, z) = illinois(lambda m0: shoot(m0, lam, eta, steps), lo, hi, flo, fhi, 1e-14 * hi)
    return x, z


def chord_angle(lam, eta, steps):
    x, z = solve_cantilever(lam, eta, steps)
    return math.atan2(z, x)


def overhang(eta, steps):
    """l*/c0: the overhang at which the chord angle is 41.5 deg (bisection over l)."""
    lo = max(math.sqrt(2.0 * eta), 1e-3)     # straight up to here
    hi = lo + 1.0
    while chord_angle(hi, eta, steps) < CHORD:
        lo, hi = hi, hi + 1.0
    while hi - lo > 1e-11 * hi:
        mid = 0.5 * (lo + hi)
        if chord_angle(mid, eta, steps) < CHORD:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi)


class Reading:
    """c_read/c0 for each eta, at N and 2N steps; remembers the largest relative difference."""

    def __init__(self, steps):
        self.steps, self.worst, self.cache = steps, 0.0, {}

    def __call__(self, eta):
        if eta not in self.cache:
            coarse, fine = overhang(eta, self.steps), overhang(eta, 2 * self.steps)
            self.worst = max(self.worst, abs(coarse - fine) / fine)
            self.cache[eta] = fine / 2.0
        return self.cache[eta]


def peirce_formula(l, theta):
    """Peirce's c = l (cos(theta/2) / (8 tan theta))^(1/3) (drape's PeirceBendingLength)."""
    return l * (math.cos(theta / 2) / (8 * math.tan(theta))) ** (1.0 / 3.0)


def fabric_row(label, rho, b, two_hb, reading):
    """One fabric: W as rho (kg/m^2), B (gf*cm^2/cm), 2HB (gf*cm/cm)."""
    w, d, h = rho * G, b * GF_CM2, two_hb / 2 * GF_CM
    c0 = (d / w) ** (1.0 / 3.0)
    eta = h / (w * c0 * c0)
    c_read = reading(eta) * c0
    b_app = w * c_read ** 3 / GF_CM2
    return (f"| {label} | {b:g} | {two_hb:g} | {h:.3e} | {eta:.4f} | {100 * c_read:.3f} | "
            f"{100 * c0:.3f} | {2 * 100 * c_read:.3f} | {b_app:.4f} | {b_app / b:.3f} |")


def main():
    parser = argparse.ArgumentParser(description=" ".join(__doc__.split("\n\n")[0].split()))
    parser.add_argument("--steps", type=int, default=400, help="RK4 steps over the strip (N)")
    parser.add_argument("--rho", type=float, default=0.12, help="kg/m^2 (W 12 mg/cm^2)")
    parser.add_argument("--B", default="0.12,0.08", help="B_warp,B_weft (gf*cm^2/cm)")
    parser.add_argument("--2HB", dest="two_hb", default="0,0.025,0.05,0.075,0.10,0.125,0.15",
                        help="2HB values (gf*cm/cm)")
    parser.add_argument("--eta", default="0,0.05,0.1,0.2,0.3,0.5,0.75,1,1.5,2",
                        help="eta values for the universal curve")
    args = parser.parse_args()
    reading = Reading(args.steps)

    print("(a) c_read/c0 against eta = H/(w c0^2), c0 = (D/w)^(1/3), chord 41.5 deg")
    print("| eta | l*/c0 | c_read/c0 | B_app/B = (c_read/c0)^3 |")
    print("|---|---|---|---|")
    for eta in (float(v) for v in args.eta.split(",")):
        r = reading(eta)
        print(f"| {eta:g} | {2 * r:.5f} | {r:.5f} | {r ** 3:.4f} |")
    r0 = reading(0.0)
    print(f"eta = 0: c_read = l*/2 = {r0:.5f} c0 ({100 * (r0 - 1):+.2f} %; B_app/B = {r0 ** 3:.4f});"
          f" Peirce's formula at (l*, 41.5 deg) gives {peirce_formula(2 * r0, CHORD):.5f} c0")

    print("\n(b) fabrics: rho = %g kg/m^2, g = %g m/s^2" % (args.rho, G))
    print("| fabric | B (gf·cm²/cm) | 2HB (gf·cm/cm) | H (N) | eta | c_read (cm) | c0 (cm) | "
          "l* (cm) | B_app (gf·cm²/cm) | B_app/B |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for label, b in zip(("cotton warp", "cotton weft"), (float(v) for v in args.B.split(","))):
        for two_hb in (float(v) for v in args.two_hb.split(",")):
            print(fabric_row(label, args.rho, b, two_hb, reading))
    print(fabric_row("Matsudaira cotton broad", 0.12, 0.118, 0.124, reading))
    print(fabric_row("Matsudaira polyester faille", 0.12, 0.019, 0.007, reading))
    print(f"\nstep halving: largest relative change of l* from N = {args.steps} to "
          f"{2 * args.steps} steps: {reading.worst:.1e}")


if __name__ == "__main__":
    main()
