"""Tables and figures of `./wheelchair report` (tools/report.py) from the Table 2 runs:
matplotlib plots in the style of the paper's Figures 5, 7 and 8, and the markdown report with
the paper's Tables 1 and 2 beside ours."""
import bisect
import math
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import yaml  # noqa: E402

import table2_metrics as metrics  # noqa: E402

DPI = 72


def load_map(map_yaml):
    """(image as float array, extent [x0, x1, y0, y1] in cm) of a map_server YAML + PGM."""
    map_yaml = pathlib.Path(map_yaml)
    info = yaml.safe_load(map_yaml.read_text())
    data = (map_yaml.parent / info["image"]).read_bytes()
    fields, pos = [], 0
    while len(fields) < 4:  # P5 header: magic, width, height, maxval; '#' comments
        while data[pos:pos + 1].isspace():
            pos += 1
        if data[pos:pos + 1] == b"#":
            pos = data.index(b"\n", pos) + 1
            continue
        end = pos
        while not data[end:end + 1].isspace():
            end += 1
        fields.append(data[pos:end])
        pos = end
    width, height, maxval = int(fields[1]), int(fields[2]), int(fields[3])
    image = np.frombuffer(data[pos + 1:pos + 1 + width * height], dtype=np.uint8)
    image = image.reshape(height, width).astype(float) / maxval
    res, (ox, oy) = info["resolution"], info["origin"][:2]
    extent = [100 * ox, 100 * (ox + width * res), 100 * oy, 100 * (oy + height * res)]
    return image, extent


def _draw_map(ax, map_image, extent):
    # the paper draws free space black and obstacles white; ours keeps the usual light map
    ax.imshow(0.55 + 0.45 * map_image, cmap="gray", vmin=0, vmax=1, extent=extent,
              origin="upper", interpolation="nearest")


def _cm(samples, i):
    return [100 * s[i] for s in samples]


def _zoom(ax, record, margin=60):
    xs = _cm(record["plan"], 0) + _cm(record["truth"], 1)
    ys = _cm(record["plan"], 1) + _cm(record["truth"], 2)
    cx, cy = (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2
    half = max(max(xs) - min(xs), max(ys) - min(ys)) / 2 + margin
    ax.set_xlim(cx - half, cx + half)
    ax.set_ylim(cy - half, cy + half)
    ax.set_aspect("equal")
    ax.set_xlabel("X [cm]")
    ax.set_ylabel("Y [cm]")


def run_figures(records, map_yaml, out):
    """run_NN.png: left the paper's Fig. 7 (reference solid, control = true trajectory dashed),
    middle its Fig. 8 (reference solid, localizer estimate dashed), right both distances to the
    reference over time (what MSEre and MSErc average, squared)."""
    map_image, extent = load_map(map_yaml)
    for r in records:
        if "truth" not in r or not r["plan"]:
            continue
        fig, axes = plt.subplots(1, 3, figsize=(13, 4.4), dpi=DPI,
                                 gridspec_kw={"width_ratios": [1, 1, 1.1]})
        panels = (("control", r["truth"], "tab:blue", "mse_re_cm2", "MSEre"),
                  ("estimation", r["estimate"], "tab:red", "mse_rc_cm2", "MSErc"))
        path = [(p[0], p[1]) for p in r["plan"]]
        t0, t1 = r["window"]
        for ax, (label, samples, color, key, short) in zip(axes, panels):
            _draw_map(ax, map_image, extent)
            ax.plot(_cm(r["plan"], 0), _cm(r["plan"], 1), "k-", lw=1.6, label="reference")
            ax.plot(_cm(samples, 1), _cm(samples, 2), "--", color=color, lw=1.4, label=label)
            ax.plot(100 * r["start"][0], 100 * r["start"][1], "o", color="tab:blue", ms=8,
                    mfc="none", mew=2)
            ax.plot(100 * r["goal"][0], 100 * r["goal"][1], "s", color="tab:red", ms=8,
                    mfc="none", mew=2)
            _zoom(ax, r)
            ax.set_title(f"{short} = {r[key]:.2f} cm²", fontsize=10)
            ax.legend(loc="best", fontsize=8)
            inside = metrics.in_window(samples, t0, t1)
            axes[2].plot([s[0] - t0 for s in inside],
                         [100 * metrics.distance_to_path((s[1], s[2]), path) for s in inside],
                         "-" if label == "control" else ".-", color=color, lw=1.0, ms=3,
                         label=f"{label} ({short})")
        axes[2].set_xlabel("time since tracking began [s]")
        axes[2].set_ylabel("distance to the reference [cm]")
        axes[2].grid(True, alpha=0.3)
        axes[2].legend(loc="best", fontsize=8)
        fig.suptitle(f"Simulation {r['index']}: {r['name']} ({r['via']})", fontsize=10)
        fig.tight_layout()
        fig.savefig(pathlib.Path(out) / f"run_{r['index']:02d}.png", dpi=DPI)
        plt.close(fig)


def overview_figure(records, map_yaml, target):
    """Every reference path on the map, start circles and goal squares (the paper's Fig. 5)."""
    map_image, extent = load_map(map_yaml)
    fig, ax = plt.subplots(figsize=(5.5, 6.3), dpi=DPI)
    _draw_map(ax, map_image, extent)
    for r in records:
        if r.get("plan"):
            ax.plot(_cm(r["plan"], 0), _cm(r["plan"], 1), "-", lw=1.3)
            ax.annotate(str(r["index"]), (100 * r["start"][0], 100 * r["start"][1]),
                        fontsize=8, xytext=(3, 3), textcoords="offset points")
        ax.plot(100 * r["start"][0], 100 * r["start"][1], "o", color="tab:blue", ms=6, mfc="none")
        ax.plot(100 * r["goal"][0], 100 * r["goal"][1], "s", color="tab:red", ms=6, mfc="none")
    ax.set_xlim(extent[0], extent[1])
    ax.set_ylim(extent[2], extent[3])
    ax.set_aspect("equal")
    ax.set_xlabel("X [cm]")
    ax.set_ylabel("Y [cm]")
    ax.set_title("Table 2 routes in flat (o start, □ goal)", fontsize=10)
    fig.tight_layout()
    fig.savefig(target, dpi=DPI)
    plt.close(fig)


def truth_at(truth, t):
    """The true (x, y) at time t, linearly interpolated between the 50 Hz samples."""
    times = [s[0] for s in truth]
    i = bisect.bisect_left(times, t)
    if i <= 0:
        return truth[0][1:3]
    if i >= len(truth):
        return truth[-1][1:3]
    a, b = truth[i - 1], truth[i]
    w = 0.0 if b[0] == a[0] else (t - a[0]) / (b[0] - a[0])
    return (a[1] + w * (b[1] - a[1]), a[2] + w * (b[2] - a[2]))


def table1_rows(record, updates=(1, 3, 10, 20)):
    """The paper's Table 1 on one of our runs: the k-th localizer estimate (filter update k
    after the goal was sent) against the true pose at its stamp, in cm."""
    rows = []
    for k in updates:
        if k > len(record.get("estimate", [])):
            continue
        t, x, y = record["estimate"][k - 1][:3]
        tx, ty = truth_at(record["truth"], t)
        rows.append({"iterations": k, "true": (100 * tx, 100 * ty), "estimate": (100 * x, 100 * y),
                     "error": 100 * math.hypot(x - tx, y - ty)})
    return rows


def _fmt(v, digits=1):
    return "–" if v is None or (isinstance(v, float) and math.isnan(v)) else f"{v:.{digits}f}"


def _table1(records, bench_rows, bench_problem):
    lines = ["## Table 1 — KLD localization: true pose vs best estimate", ""]
    first = next((r for r in records if "estimate" in r), None)
    ours = {row["iterations"]: row for row in table1_rows(first)} if first else {}
    lines += ["| iterations | paper true (x, y) cm | paper estimate | paper error [cm] | "
              "ours true (x, y) cm | ours estimate | ours error [cm] |",
              "|---|---|---|---|---|---|---|"]
    for p in metrics.PAPER_TABLE1:
        o = ours.get(p["iterations"])
        lines.append("| %d | (%g, %g) | (%g, %g) | %.1f | %s | %s | %s |" % (
            p["iterations"], *p["true"], *p["estimate"], p["error"],
            "(%.1f, %.1f)" % o["true"] if o else "–", "(%.1f, %.1f)" % o["estimate"] if o else "–",
            _fmt(o["error"]) if o else "–"))
    lines += ["", "Ours: simulation 1 of Table 2, the k-th filter update (`/kld_pose`) after the "
              "goal was sent, against the simulator's true pose at the same instant. The paper "
              "starts from a global (uniform) prior; ours from the start pose given on "
              "`/initialpose` (σ = 3 cm, 1.7°), as a user's \"2D Pose Estimate\" would.", ""]
    if bench_rows:
        lines += ["KLD package benchmark (`./wheelchair bench kld`, `bench/kld/run`):", "",
                  "| case | method | metric | value | unit |", "|---|---|---|---|---|"]
        for row in bench_rows:
            lines.append(f"| {row.get('case')} | {row.get('method')} | {row.get('metric')} | "
                         f"{_fmt(row.get('value'), 3)} | {row.get('unit')} |")
    else:
        lines.append(f"KLD package benchmark: {bench_problem}.")
    return lines + [""]


def _table2(records):
    lines = ["## Table 2 — MSE between the reference path and the localizer's estimate (MSErc) "
             "and the true trajectory (MSEre)", "",
             "| simulation | paper MSErc [cm²] | paper MSEre [cm²] | route | ours MSErc [cm²] | "
             "ours MSEre [cm²] | goal error [cm / °] | outcome |",
             "|---|---|---|---|---|---|---|---|"]
    for i in range(max(10, len(records))):
        r = next((r for r in records if r["index"] == i + 1), None)
        paper_rc = metrics.PAPER_TABLE2["mse_rc"][i] if i < 10 else None
        paper_re = metrics.PAPER_TABLE2["mse_re"][i] if i < 10 else None
        if r is None:
            lines.append(f"| {i + 1} | {paper_rc} | {paper_re} | not run | – | – | – | – |")
            continue
        goal = (f"{_fmt(100 * r['goal_position_error_m'])} / {_fmt(r['goal_heading_error_deg'])}"
                if "goal_position_error_m" in r else "–")
        outcome = r["outcome"] + (" + collision" if r.get("collision") and
                                  r["outcome"] != "collision" else "")
        lines.append(f"| {i + 1} | {paper_rc} | {paper_re} | {r['name']}: {r['via']} | "
                     f"{_fmt(r.get('mse_rc_cm2'), 2)} | {_fmt(r.get('mse_re_cm2'), 2)} | {goal} | "
                     f"{outcome} |")
    def finite(key):
        return [r[key] for r in records if key in r and math.isfinite(r[key])]

    rc_values, re_values = finite("mse_rc_cm2"), finite("mse_re_cm2")
    rc, re = metrics.mean_std(rc_values), metrics.mean_std(re_values)
    paper = metrics.PAPER_TABLE2
    lines.append(f"| **Mean** | {paper['mean']['mse_rc']} | {paper['mean']['mse_re']} | "
                 f"(ours over the runs with samples: {len(rc_values)} / {len(re_values)}) | "
                 f"**{_fmt(rc[0], 2)}** | **{_fmt(re[0], 2)}** | | |")
    lines.append(f"| **Std** | {paper['std']['mse_rc']} | {paper['std']['mse_re']} | | "
                 f"{_fmt(rc[1], 2)} | {_fmt(re[1], 2)} | | |")
    complete = len(rc_values) == len(records) and len(re_values) == len(records)
    return lines, rc, re, complete


def write_markdown(records, bench_rows, bench_problem, target, speed, nice=None,
                   wall_time_s=None):
    """report.md; returns True when every run reached its goal and both means beat the paper."""
    t2, rc, re, complete = _table2(records)
    reached = [r for r in records if r.get("outcome") == "goal_reached" and not r.get("collision")
               and r.get("goal_position_error_m", 1.0) < 0.10
               and r.get("goal_heading_error_deg", 180.0) < 10.0]
    ok = (complete and len(reached) == len(records) and rc[0] < metrics.PAPER_TABLE2["mean"]["mse_rc"]
          and re[0] < metrics.PAPER_TABLE2["mean"]["mse_re"])
    lines = ["# The paper's Tables 1 and 2, reproduced on the simulated chair", "",
             f"Verdict: **{'PASS' if ok else 'FAIL'}** — {len(reached)}/{len(records)} goals "
             f"reached within 10 cm and 10° without collision; mean MSErc {_fmt(rc[0], 2)} cm² "
             f"(paper 5.8), mean MSEre {_fmt(re[0], 2)} cm² (paper 11.2).", "",
             "Setup: world `flat` (test/worlds), pairs `test/table2/flat_pairs.yaml`; simulator "
             f"(wheelchair_sim, eq. 15 with rolling resistance, laser noise 1 cm, odometry "
             f"errors) at {speed:g}× real time behind the CAN path (base driver over UDP); the "
             "one-process chair: map server, KLD localizer, harmonic planner, navigator, "
             "controller, base driver, safety supervisor, HMI"
             + (f"; simulator and chair at nice {nice} (as deployed: `Nice=-5` in "
                "deploy/wheelchair.service)" if nice is not None else "")
             + ". Protocol per pair: teleport the chair to the start, `/initialpose` there, "
             "the goal through the navigator's `move_base` action, wait for the controller's "
             "`goal_reached` and the action's result"
             + (f". All runs in one go, rviz snapshots included: {wall_time_s / 60:.1f} min wall"
                if wall_time_s else "") + ".", "",
             "Definitions: reference = the planned path `/plan` (axle-centre poses) as a "
             "polyline. MSEre = mean over the true trajectory (`/sim/ground_truth`, 50 Hz) of the "
             "squared distance to the nearest point of the reference; MSErc = the same over the "
             "localizer's estimates (`/kld_pose`, every filter update). Samples from the "
             "controller's first `tracking` to `goal_reached`. Std: sample std (n − 1), which "
             "reproduces the paper's Std row from its ten values.", ""]
    lines += t2 + [""] + _table1(records, bench_rows, bench_problem)
    lines += ["## Figures", "", "![routes](overview.png)", ""]
    for r in records:
        if "truth" in r:
            lines.append(f"- simulation {r['index']}: [plots](run_{r['index']:02d}.png) "
                         f"(reference vs control, reference vs estimate), "
                         f"[rviz](snapshots/run_{r['index']:02d}.png)")
    pathlib.Path(target).write_text("\n".join(lines) + "\n")
    return ok
