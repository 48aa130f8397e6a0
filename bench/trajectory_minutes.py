#!/usr/bin/env python3
"""Per-minute error of a trajectory against the truth, to see whether drift is bounded.

    bench/trajectory_minutes.py EST.tum TRUTH.tum [ODOMETRY.tum]

Poses are associated by stamp (nearest within 20 ms), the estimate is rigidly aligned onto the
truth in the plane (closed-form 2D Horn/Umeyama over all associated poses, as ATE aligns), and
for every minute of the run it prints the error percentiles (50/90/max, metres) and the
distance ratio: path length of the estimate over that of the truth in that minute, both over
poses a second apart, and true_m, the truth's path length (a run's last, partial minute may hold
a few metres and a turn at the dock, where a ratio says little). With an odometry trajectory,
its distance ratio too. Plain Python: no third-party modules.
"""
import bisect
import math
import sys


def read_tum(path):
    poses = []
    for line in open(path):
        fields = line.split()
        if not fields or fields[0].startswith("#"):
            continue
        t, x, y = float(fields[0]), float(fields[1]), float(fields[2])
        poses.append((t, x, y))
    poses.sort()
    return poses


def associate(estimate, truth, max_dt=0.02):
    stamps = [p[0] for p in truth]
    pairs = []
    for e in estimate:
        i = bisect.bisect_left(stamps, e[0])
        best = min((j for j in (i - 1, i) if 0 <= j < len(truth)),
                   key=lambda j: abs(stamps[j] - e[0]), default=None)
        if best is not None and abs(stamps[best] - e[0]) <= max_dt:
            pairs.append((e, truth[best]))
    return pairs


def align_2d(pairs):
    """Rotation angle and translation moving the estimate onto the truth (least squares)."""
    n = len(pairs)
    ex = sum(e[1] for e, _ in pairs) / n
    ey = sum(e[2] for e, _ in pairs) / n
    tx = sum(t[1] for _, t in pairs) / n
    ty = sum(t[2] for _, t in pairs) / n
    sxx = sum((e[1] - ex) * (t[1] - tx) + (e[2] - ey) * (t[2] - ty) for e, t in pairs)
    sxy = sum((e[1] - ex) * (t[2] - ty) - (e[2] - ey) * (t[1] - tx) for e, t in pairs)
    angle = math.atan2(sxy, sxx)
    c, s = math.cos(angle), math.sin(angle)
    return lambda x, y: (tx + c * (x - ex) - s * (y - ey), ty + s * (x - ex) + c * (y - ey))


def percentile(values, q):
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, int(round(q * (len(ordered) - 1))))]


def path_by_minute(poses, start, step_s=1.0):
    """Path length in each minute, over poses a second apart (per-scan jitter is no distance)."""
    sampled = []
    for pose in poses:
        if not sampled or pose[0] - sampled[-1][0] >= step_s:
            sampled.append(pose)
    lengths = {}
    for a, b in zip(sampled, sampled[1:]):
        minute = int((b[0] - start) // 60)
        lengths[minute] = lengths.get(minute, 0.0) + math.hypot(b[1] - a[1], b[2] - a[2])
    return lengths


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    estimate, truth = read_tum(sys.argv[1]), read_tum(sys.argv[2])
    odometry = read_tum(sys.argv[3]) if len(sys.argv) > 3 else None
    pairs = associate(estimate, truth)
    if len(pairs) < 3:
        sys.exit("fewer than 3 poses associate by stamp")
    to_truth = align_2d(pairs)
    start = pairs[0][1][0]
    errors = {}
    for e, t in pairs:
        x, y = to_truth(e[1], e[2])
        errors.setdefault(int((t[0] - start) // 60), []).append(math.hypot(x - t[1], y - t[2]))
    truth_path = path_by_minute([t for _, t in pairs], start)
    estimate_path = path_by_minute([e for e, _ in pairs], start)
    odometry_path = path_by_minute(odometry, start) if odometry else {}
    header = "%6s %8s %8s %8s %8s %10s" % ("minute", "err_p50", "err_p90", "err_max", "true_m",
                                           "dist_ratio")
    print(header + (" %10s" % "odom_ratio" if odometry else ""))
    for minute in sorted(errors):
        values = errors[minute]
        true_m = truth_path.get(minute, 0.0)
        ratio = estimate_path.get(minute, 0.0) / true_m if true_m > 0 else float("nan")
        row = "%6d %8.3f %8.3f %8.3f %8.1f %10.3f" % (minute, percentile(values, 0.5),
                                                      percentile(values, 0.9), max(values),
                                                      true_m, ratio)
        if odometry:
            odom_ratio = odometry_path.get(minute, 0.0) / true_m if true_m > 0 else float("nan")
            row += " %10.3f" % odom_ratio
        print(row)
    every = [v for values in errors.values() for v in values]
    print("all    %8.3f %8.3f %8.3f   rmse %.3f" % (
        percentile(every, 0.5), percentile(every, 0.9), max(every),
        math.sqrt(sum(v * v for v in every) / len(every))))


if __name__ == "__main__":
    main()
