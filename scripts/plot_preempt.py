"""Plots pan and tilt against time from record_preempt.py's CSV. Usage: plot_preempt.py IN.csv OUT.png"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main():
    with open(sys.argv[1]) as source:
        rows = list(csv.DictReader(source))
    t = [float(row["t"]) for row in rows]
    figure, axes = plt.subplots(figsize=(7, 3.2), dpi=100)
    axes.plot(t, [float(row["pan"]) for row in rows], ".-", label="pan")
    axes.plot(t, [float(row["tilt"]) for row in rows], ".-", label="tilt")
    for row in rows:
        if row["event"]:
            axes.axvline(float(row["t"]), color="grey", linestyle=":")
            axes.annotate(row["event"], (float(row["t"]) + 0.03, 1.55), rotation=90, fontsize=7, va="top", ha="left")
    axes.set_xlabel("time (s), ptz_state at 10 Hz")
    axes.set_ylabel("rad")
    axes.set_ylim(-1.0, 1.6)
    axes.grid(alpha=0.3)
    axes.legend(loc="lower left")
    axes.set_title("A goal preempted mid-way: the trapezoid, then the retarget without a stop", fontsize=9)
    figure.tight_layout()
    figure.savefig(sys.argv[2])


if __name__ == "__main__":
    main()
