#!/usr/bin/env python3
"""Writes chosen_floater_rao.csv: displacement RAOs of a generic floater, chosen from simple formulas (not taken
from any vessel; see README.md). Standard library only; run from this folder: python3 make_chosen_floater_rao.py"""
import math

G = 9.81
HEADINGS = [0, 45, 90, 135, 180, 225, 270, 315]    # [deg] direction the waves travel towards, from the bow to port
OMEGAS = [round(0.1 + 0.1 * i, 1) for i in range(35)]  # [rad/s] 0.1 ... 3.5


def cutoff(omega, corner):
    """Low-pass factor 1/(1 + (ω/ω_c)^4): a hull much longer than the wave does not follow it."""
    return 1.0 / (1.0 + (omega / corner) ** 4)


def heave(omega):
    """One degree of freedom, natural period 20 s, damping ratio 0.15: amplitude and phase lag [deg]."""
    r = omega / (2 * math.pi / 20.0)
    amplitude = 1.0 / math.hypot(1 - r * r, 2 * 0.15 * r) * cutoff(omega, 1.2)
    return amplitude, math.degrees(math.atan2(2 * 0.15 * r, 1 - r * r))


def signed(amplitude, lag_if_positive):
    """|A| with the lag of +A, or the lag shifted by 180 deg for a negative A."""
    return abs(amplitude), (lag_if_positive if amplitude >= 0 else lag_if_positive - 180.0)


def rows():
    for heading in HEADINGS:
        b = math.radians(heading)
        for omega in OMEGAS:
            k = omega * omega / G  # deep water
            # Long waves: the floater rides the orbit (surge, sway a quarter period after the crest) and the slope.
            surge = signed(math.cos(b) * cutoff(omega, 0.8), 90.0)
            sway = signed(math.sin(b) * cutoff(omega, 0.8), 90.0)
            slope = math.degrees(k)  # [deg/m] wave slope per metre of amplitude
            roll = signed(math.sin(b) * slope * cutoff(omega, 0.6), 90.0)
            pitch = signed(math.cos(b) * slope * cutoff(omega, 0.7), -90.0)
            yaw = (0.1 * abs(math.sin(2 * b)) * slope * cutoff(omega, 0.7), 0.0)
            yield [heading, omega, *surge, *sway, *heave(omega), *roll, *pitch, *yaw]


def main():
    names = ["heading [deg]", "omega [rad/s]"]
    for dof, unit in [("surge", "m/m"), ("sway", "m/m"), ("heave", "m/m"), ("roll", "deg/m"), ("pitch", "deg/m"),
                      ("yaw", "deg/m")]:
        names += [f"{dof}_amplitude [{unit}]", f"{dof}_phase [deg]"]
    with open("chosen_floater_rao.csv", "w", encoding="utf-8") as out:
        out.write("# Displacement RAOs of a generic floater: values chosen from formulas (make_chosen_floater_rao.py),\n")
        out.write("# not taken from a vessel. Phases lag the wave crest at the RAO origin (OrcaFlex's convention).\n")
        out.write(",".join(names) + "\n")
        for r in rows():
            out.write(",".join(f"{v:.6g}" for v in r) + "\n")


if __name__ == "__main__":
    main()
