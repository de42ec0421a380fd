#!/usr/bin/env python3
"""tactip_plot: the figures of tactip-sim, drawn with matplotlib from the CSVs `tactip` writes.

Subcommands (see --help of each):
  check     exit 0 when matplotlib can be imported (prints its version)
  heatmap   one number per design of a sweep (designs.csv) over 1 or 2 swept keys
  pareto    error against run time, one panel per error column (`tactip accuracy`'s CSV)
  run-motion, run-quiver, run-markers, run-indentation
            the figures of one run (`tactip plot`'s CSVs, see docs/viewer-and-plots.md "Figures of one run")

Uses only the Python standard library and matplotlib (Agg backend, no display). PNGs are
rendered in memory and then written atomically (temporary file + rename): a failure leaves
no file. Exit codes: 0 done, 2 bad input (one line on stderr), 3 matplotlib missing.
"""

import argparse
import csv
import io
import math
import os
import sys
import textwrap

PROG = "tactip_plot"
DPI = 120
MISSING_GREY = "#bbbbbb"


class InputProblem(Exception):
    """Bad input: printed as one line, exit code 2."""


# ------------------------------------------------------------------ input and output

def pyplot():
    """matplotlib.pyplot on the Agg backend; exits 3 with a one-line message if missing."""
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError as e:
        print(f"{PROG}: cannot import matplotlib: {e}", file=sys.stderr)  # the caller names the fix
        sys.exit(3)
    return plt


def read_csv(path, needed):
    """Rows of `path` as dicts; every column in `needed` must be in the header."""
    try:
        with open(path, newline="", encoding="utf-8") as f:
            reader = csv.DictReader(f)
            header = reader.fieldnames or []
            rows = list(reader)
    except OSError as e:
        raise InputProblem(f"cannot read '{path}': {e.strerror}")
    for col in needed:
        if col not in header:
            raise InputProblem(f"'{path}' has no column '{col}' (columns: {', '.join(header)})")
    if not rows:
        raise InputProblem(f"'{path}' has no data rows")
    return rows


def number(text):
    """A CSV cell as float; empty, 'nan', 'inf' (an event that never came) and unparsable
    cells are NaN: no value to plot."""
    try:
        value = float(text)
    except (TypeError, ValueError):
        return math.nan
    return value if math.isfinite(value) else math.nan


def flag(text):
    """A 0/1 CSV cell as bool (empty or missing: False)."""
    v = number(text)
    return not math.isnan(v) and v != 0.0


def save_png(fig, out, dpi=DPI, palette=False):
    """Renders `fig` to memory at `dpi` (with `palette`: as 256 colours, through Pillow, which
    Debian's matplotlib depends on), then writes `out` atomically."""
    folder = os.path.dirname(out) or "."
    if not os.path.isdir(folder):
        raise InputProblem(f"cannot write '{out}': folder '{folder}' does not exist")
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=dpi)
    if palette:
        from PIL import Image
        small = io.BytesIO()
        Image.open(io.BytesIO(buf.getvalue())).convert("RGB").quantize(colors=256).save(small, format="png",
                                                                                        optimize=True)
        buf = small
    tmp = f"{out}.tmp.{os.getpid()}"
    try:
        with open(tmp, "wb") as f:
            f.write(buf.getvalue())
        os.replace(tmp, out)
    except OSError as e:
        if os.path.exists(tmp):
            os.remove(tmp)
        raise InputProblem(f"cannot write '{out}': {e.strerror}")


def ordered_unique(values):
    """Values in order of first appearance (the sweep's order)."""
    seen = {}
    for v in values:
        seen.setdefault(v, None)
    return list(seen)


# ------------------------------------------------------------------ heatmap

def cell_text(v):
    if math.isnan(v):
        return "n/a"
    if math.isinf(v):
        return "inf" if v > 0 else "-inf"
    return f"{v:.3g}"


def heatmap_grid(rows, x_key, y_key, value):
    """(x values, y values, grid[iy][ix]) from the CSV rows; missing cells are NaN."""
    xs = ordered_unique(r[x_key] for r in rows)
    ys = ordered_unique(r[y_key] for r in rows) if y_key else [""]
    grid = [[math.nan] * len(xs) for _ in ys]
    filled = set()
    for r in rows:
        ix, iy = xs.index(r[x_key]), ys.index(r[y_key]) if y_key else 0
        if (ix, iy) in filled:
            where = f"{x_key}={r[x_key]}" + (f", {y_key}={r[y_key]}" if y_key else "")
            raise InputProblem(f"several rows for {where}: a heatmap needs one row per cell (sweep 1 or 2 keys)")
        filled.add((ix, iy))
        grid[iy][ix] = number(r[value])
    return xs, ys, grid


def cmd_heatmap(a):
    rows = read_csv(a.csv, [a.x, a.value] + ([a.y] if a.y else []))
    xs, ys, grid = heatmap_grid(rows, a.x, a.y, a.value)
    plt = pyplot()
    import matplotlib.colors as mcolors
    import numpy as np

    # Colour scale over the finite values; NaN and infinities are grey.
    data = np.array(grid, dtype=float)
    finite = np.isfinite(data)
    masked = np.ma.masked_where(~finite, data)
    lo, hi = (float(data[finite].min()), float(data[finite].max())) if finite.any() else (0.0, 1.0)
    if hi == lo:
        half = 0.5 * (abs(lo) or 1.0)
        lo, hi = lo - half, hi + half
    cmap = plt.get_cmap("viridis").copy()
    cmap.set_bad(MISSING_GREY)
    norm = mcolors.Normalize(lo, hi)

    # Size: cells wide enough for their text and tick labels; big grids lose the numbers.
    nx, ny = len(xs), len(ys)
    annotate = nx * ny <= 600
    chars = max([len(cell_text(v)) for row in grid for v in row] + [len(x) for x in xs])
    cell_w = min(max(0.7, 0.085 * chars + 0.25), 1.4)
    slant = 0.085 * max(len(x) for x in xs) + 0.25 > cell_w
    strip = ny == 1  # a single row: taller cells, colour bar below
    width = min(max(5.0, nx * cell_w + (1.5 if strip else 2.8)), 30.0)
    height = min(max(3.0, ny * 0.45 + 2.0 + (0.6 if slant else 0.0) + (1.2 if strip else 0.0)), 30.0)
    fig, ax = plt.subplots(figsize=(width, height), layout="constrained")
    im = ax.imshow(masked, cmap=cmap, norm=norm, aspect="auto", interpolation="nearest")

    # Numbers in the cells, dark on light colours and light on dark ones.
    if annotate:
        for iy in range(ny):
            for ix in range(nx):
                v = grid[iy][ix]
                rgb = cmap(norm(v)) if math.isfinite(v) else mcolors.to_rgba(MISSING_GREY)
                light = 0.299 * rgb[0] + 0.587 * rgb[1] + 0.114 * rgb[2] > 0.55
                ax.text(ix, iy, cell_text(v), ha="center", va="center", fontsize=9,
                        color="black" if light else "white")

    # Axes: first key as rows (top to bottom), second as columns; a 1-D strip has no y axis.
    ax.set_xticks(range(nx), xs, rotation=40 if slant else 0, ha="right" if slant else "center")
    ax.set_xlabel(a.x)
    if a.y:
        ax.set_yticks(range(ny), ys)
        ax.set_ylabel(a.y)
    else:
        ax.set_yticks([])
    ax.set_title(textwrap.fill(a.title or a.value, max(20, int(width / 0.11))))  # ~0.11 in per character
    if strip:
        bar = fig.colorbar(im, ax=ax, orientation="horizontal", location="bottom", fraction=0.12, aspect=40)
    else:
        bar = fig.colorbar(im, ax=ax, fraction=0.08 if nx > 3 else 0.15, pad=0.03)
    bar.set_label(f"{a.value} ({a.unit})" if a.unit else a.value)
    if not finite.any():
        bar.set_ticks([])
    save_png(fig, a.out)


# ------------------------------------------------------------------ pareto

def pareto_front(points):
    """Indices of the non-dominated points of [(x, y), ...], smaller being better in both.

    A point is dominated when another is at most as slow and at most as wrong (|y|), and
    strictly better in one of the two. Points with a NaN coordinate are never on the front.
    Returned in order of increasing x (then increasing |y|, then input order).
    """
    ok = [i for i, (x, y) in enumerate(points) if not (math.isnan(x) or math.isnan(y))]
    front = []
    for i in ok:
        xi, yi = points[i][0], abs(points[i][1])
        dominated = any(
            points[j][0] <= xi and abs(points[j][1]) <= yi and (points[j][0] < xi or abs(points[j][1]) < yi)
            for j in ok if j != i)
        if not dominated:
            front.append(i)
    return sorted(front, key=lambda i: (points[i][0], abs(points[i][1]), i))


class Setting:
    """One row of the accuracy CSV."""

    def __init__(self, row, x_col, label_col):
        self.label = row[label_col]
        self.x = number(row[x_col])
        self.row = row
        self.default = flag(row.get("is_default"))
        self.reference = flag(row.get("is_reference"))
        self.healthy = row.get("healthy") in (None, "") or flag(row.get("healthy"))

    def y(self, col):
        return number(self.row[col])


def panel_front(settings, col):
    """The healthy settings on the Pareto front of panel `col`, fastest first."""
    healthy = [s for s in settings if s.healthy and s.x > 0]
    return [healthy[i] for i in pareto_front([(s.x, s.y(col)) for s in healthy])]


def choose_y_scale(ax, ys):
    """Log when the positive errors span more than 2 decades (symlog if there are zeros), else
    linear with zero in view."""
    pos = [y for y in ys if y > 0]
    nonpos = any(y <= 0 for y in ys)
    if pos and max(pos) / min(pos) > 100:
        if nonpos:
            ax.set_yscale("symlog", linthresh=min(pos), linscale=1.0)
            low = min(min(ys), 0.0)
            ax.set_ylim(low - 0.3 * min(pos) if low == 0 else low * 2, max(pos) * 3)
        else:
            ax.set_yscale("log")
            ax.set_ylim(min(pos) / 3, max(pos) * 3)
        return
    low, high = min(ys + [0.0]), max(ys + [0.0])
    span = (high - low) or (abs(high) or 1.0)
    ax.set_ylim(low - 0.08 * span, high + 0.15 * span)


def place_labels(ax, fig, items):
    """Labels next to their points, each at the candidate offset that overlaps least with the
    labels already placed, the points and the axes' edge. items: [(x, y, text, bold)]."""
    renderer = fig.canvas.get_renderer()
    offsets = [(7, 5, "left", "bottom"), (7, -5, "left", "top"), (-7, 5, "right", "bottom"),
               (-7, -5, "right", "top"), (0, 9, "center", "bottom"), (0, -9, "center", "top"),
               (14, 14, "left", "bottom"), (-14, -14, "right", "top")]
    frame = ax.get_window_extent(renderer)
    dots = [ax.transData.transform((x, y)) for x, y, _, _ in items]
    taken = [(px - 5, py - 5, px + 5, py + 5) for px, py in dots]

    def overlap(b, boxes):
        return sum(max(0.0, min(b[2], c[2]) - max(b[0], c[0])) * max(0.0, min(b[3], c[3]) - max(b[1], c[1]))
                   for c in boxes)

    for x, y, text, bold in items:
        best = None
        for dx, dy, ha, va in offsets:
            t = ax.annotate(text, (x, y), xytext=(dx, dy), textcoords="offset points", ha=ha, va=va,
                            fontsize=8, fontweight="bold" if bold else "normal")
            e = t.get_window_extent(renderer)
            box = (e.x0, e.y0, e.x1, e.y1)
            outside = (e.width * e.height) - overlap(box, [(frame.x0, frame.y0, frame.x1, frame.y1)])
            cost = overlap(box, taken) + 2 * outside
            if best is None or cost < best[0]:
                if best is not None:
                    best[1].remove()
                best = (cost, t, box)
            else:
                t.remove()
            if cost == 0:
                break
        taken.append(best[2])


def draw_panel(ax, fig, settings, col, x_col):
    """One error column: every setting, the front as a step line, default and reference marked."""
    shown = [s for s in settings if s.x > 0 and not math.isnan(s.y(col))]
    missing = [s.label for s in settings if s not in shown]
    front = panel_front(settings, col)
    ax.set_xscale("log")
    ax.set_title(col, fontsize=10)
    ax.set_xlabel("wall time per simulated second (s)" if x_col == "wall_s_per_sim_s" else x_col, fontsize=9)
    ax.set_ylabel(col, fontsize=9)
    ax.grid(True, which="major", alpha=0.3)
    if not shown:
        ax.text(0.5, 0.5, "no values", transform=ax.transAxes, ha="center", va="center", color="grey")
        return

    # Axis ranges first: labels are placed in screen space.
    xs = [s.x for s in shown]
    ax.set_xlim(min(xs) / 2.5, max(xs) * 2.5)
    choose_y_scale(ax, [s.y(col) for s in shown])

    # The front: best error reachable at each run time.
    if front:
        fx = [s.x for s in front] + [max(xs) * 2.5]
        fy = [s.y(col) for s in front] + [front[-1].y(col)]
        ax.step(fx, fy, where="post", color="tab:green", lw=1.6, alpha=0.8, zorder=1)

    # Points: healthy (front ones green), unhealthy as red crosses, default and reference ringed.
    for s in shown:
        y = s.y(col)
        if not s.healthy:
            ax.plot(s.x, y, "x", color="red", ms=8, mew=2, zorder=3)
        else:
            ax.plot(s.x, y, "o", color="tab:green" if s in front else "tab:blue", ms=6, zorder=3)
        if s.default:
            ax.plot(s.x, y, "o", mfc="none", mec="darkorange", ms=15, mew=2.5, zorder=4)
        if s.reference:
            ax.plot(s.x, y, "s", mfc="none", mec="black", ms=13, mew=1.5, zorder=4)

    def label(s):
        tags = [t for t, on in (("default", s.default), ("reference", s.reference)) if on]
        return s.label + (f" ({', '.join(tags)})" if tags else "")

    place_labels(ax, fig, [(s.x, s.y(col), label(s), s.default or s.reference) for s in shown])
    if missing:
        ax.text(0.01, 0.01, "no value (missed or n/a): " + ", ".join(missing), transform=ax.transAxes, fontsize=7,
                color="grey", va="bottom")


def legend_handles():
    from matplotlib.lines import Line2D
    return [
        Line2D([], [], marker="o", ls="none", color="tab:blue", label="healthy, off the front"),
        Line2D([], [], marker="o", ls="none", color="tab:green", label="healthy, on the Pareto front"),
        Line2D([], [], color="tab:green", lw=1.6, label="Pareto front"),
        Line2D([], [], marker="x", ls="none", color="red", mew=2, label="unhealthy"),
        Line2D([], [], marker="o", ls="none", mfc="none", mec="darkorange", mew=2.5, ms=11, label="default"),
        Line2D([], [], marker="s", ls="none", mfc="none", mec="black", mew=1.5, ms=10, label="reference"),
    ]


def cmd_pareto(a):
    cols = [c for c in a.y.split(",") if c]
    if not cols:
        raise InputProblem("--y names no column")
    rows = read_csv(a.csv, [a.x, a.label] + cols)
    settings = [Setting(r, a.x, a.label) for r in rows]
    if a.print_front:
        for col in cols:
            print("\t".join([col] + [s.label for s in panel_front(settings, col)]))
    if not a.out:
        return
    plt = pyplot()

    # A legend row on top, then the panels, two per row.
    ncols = 1 if len(cols) == 1 else 2
    nrows = (len(cols) + ncols - 1) // ncols
    fig = plt.figure(figsize=(6.4 * ncols, 4.6 * nrows + 0.9), layout="constrained")
    grid = fig.add_gridspec(nrows + 1, ncols, height_ratios=[0.9 / 4.6] + [1.0] * nrows)
    top = fig.add_subplot(grid[0, :])
    top.axis("off")
    top.legend(handles=legend_handles(), loc="center", ncol=3 if ncols == 1 else 6, fontsize=8, frameon=False)
    fig.suptitle(a.title or "Error against run time")
    for k, col in enumerate(cols):
        ax = fig.add_subplot(grid[1 + k // ncols, k % ncols])
        draw_panel(ax, fig, settings, col, a.x)
    save_png(fig, a.out)


# ------------------------------------------------------------------ figures of one run

# How each event is drawn: (events.csv name, legend text, colour, line style).
EVENT_STYLES = [("gross_slip_onset", "gross-slip onset", "tab:red", "-"),
                ("incipient_onset", "incipient onset", "darkorange", "--"),
                ("object_fall", "object fall", "black", ":")]
RUN_FIG_DPI = 100  # the run figures are committed to docs/viewer-and-plots.md's gallery: kept small (and 256 colours)


def read_events(path):
    """{event name: time (s)} of the events that happened (events.csv of `tactip plot`)."""
    if not path:
        return {}
    rows = read_csv(path, ["event", "time_s"])
    return {r["event"]: number(r["time_s"]) for r in rows if not math.isnan(number(r["time_s"]))}


def mark_events(ax, events):
    """Vertical lines at the events, labelled in the legend."""
    for name, text, colour, style in EVENT_STYLES:
        if name in events:
            ax.axvline(events[name], color=colour, ls=style, lw=1.2, label=f"{text} {events[name]:.3f} s")


def run_title(fig, text, width_in):
    """The figure title, each line wrapped to the figure's width (~0.075 in per character)."""
    lines = [textwrap.fill(line, max(40, int(width_in / 0.075))) for line in text.split("\n")]
    fig.suptitle("\n".join(lines), fontsize=9)


def column(rows, col):
    """A numeric column as a list (NaN for empty cells)."""
    return [number(r[col]) for r in rows]


def zoom_window(events, t):
    """(start, end) of the time around the onsets and the fall (0.5 s before the first, 0.3 s
    after the last), or None when no event happened or the window is the whole run."""
    times = list(events.values())
    if not times:
        return None
    lo, hi = max(min(times) - 0.5, t[0]), min(max(times) + 0.3, t[-1])
    return (lo, hi) if hi > lo and (lo > t[0] or hi < t[-1]) else None


def draw_speeds(ax, rows, t):
    """Mean and max pin speed over time."""
    ax.plot(t, column(rows, "max_speed_px_frame"), color="tab:purple", lw=0.8, alpha=0.7, label="max over pins")
    ax.plot(t, column(rows, "mean_speed_px_frame"), color="black", lw=1.2, label="mean over pins")
    ax.set_ylabel("pin speed (px/frame)")


def cmd_run_motion(a):
    rows = read_csv(a.csv, ["time_s", "mean_disp_px", "mean_speed_px_frame", "max_speed_px_frame"])
    pins = [c for c in rows[0].keys() if c.startswith("pin") and c.endswith("_disp_px")]
    events = read_events(a.events)
    t = column(rows, "time_s")
    zoom = zoom_window(events, t)
    plt = pyplot()
    fig, axes = plt.subplots(3 if zoom else 2, 1, figsize=(8, 8.4 if zoom else 6.4), layout="constrained")

    # Displacement from the first frame: a few pins and the mean over all.
    top = axes[0]
    for c in pins:
        top.plot(t, column(rows, c), lw=0.8, alpha=0.8, label="pin " + c[3:-len("_disp_px")])
    top.plot(t, column(rows, "mean_disp_px"), color="black", lw=1.6, label="mean over pins")
    top.set_ylabel("displacement from first frame (px)")
    # Speed over the run, then (when there are events) around them, frame by frame.
    draw_speeds(axes[1], rows, t)
    if zoom:
        draw_speeds(axes[2], rows, t)
        axes[2].plot(t, column(rows, "mean_speed_px_frame"), "k.", ms=3)
        axes[2].set_xlim(*zoom)
        axes[2].set_title("around the events (dots: frames)", fontsize=8)
    for ax in axes:
        mark_events(ax, events)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7, loc="upper left", ncol=2)
        ax.set_xlabel("time (s)")
    run_title(fig, a.title, fig.get_figwidth())
    save_png(fig, a.out, RUN_FIG_DPI, palette=True)


def quiver_scale(rows, span):
    """(data units per px/frame, a round reference speed) so the fastest arrow spans ~12 % of
    the pattern."""
    speeds = [math.hypot(number(r["du_px"]), number(r["dv_px"])) for r in rows]
    fastest = max([v for v in speeds if not math.isnan(v)] + [0.0])
    if fastest <= 0:
        return 1.0, 1.0
    ref = 10 ** math.floor(math.log10(fastest))
    for step in (5, 2):
        if step * ref <= fastest:
            ref *= step
            break
    return 0.12 * span / fastest, ref


def cmd_run_quiver(a):
    rows = read_csv(a.csv, ["panel", "frame", "time_s", "u_px", "v_px", "du_px", "dv_px", "contact"])
    panels = ordered_unique(r["panel"] for r in rows)
    plt = pyplot()
    us, vs = column(rows, "u_px"), column(rows, "v_px")
    span = max(max(us) - min(us), max(vs) - min(vs), 1.0)
    gain, ref = quiver_scale(rows, span)
    fig, axes = plt.subplots(1, len(panels), figsize=(4.0 * len(panels), 5.0), layout="constrained", squeeze=False)
    for ax, panel in zip(axes[0], panels):
        sel = [r for r in rows if r["panel"] == panel]
        u, v = column(sel, "u_px"), column(sel, "v_px")
        du, dv = column(sel, "du_px"), column(sel, "dv_px")
        touching = [flag(r["contact"]) for r in sel]
        # Pins: grey, those in contact blue; arrows scaled alike in every panel.
        ax.scatter(u, v, s=6, c=["tab:blue" if c else "0.6" for c in touching], zorder=2)
        q = ax.quiver(u, v, [x * gain for x in du], [y * gain for y in dv], angles="xy", scale_units="xy", scale=1,
                      color="tab:red", width=0.006, zorder=3)
        mean = sum(math.hypot(x, y) for x, y in zip(du, dv)) / len(sel)
        ax.set_title(f"{panel}: t = {number(sel[0]['time_s']):.3f} s (frame {sel[0]['frame']})\n"
                     f"mean speed {mean:.2f} px/frame, {sum(touching)} pins in contact", fontsize=8)
        ax.quiverkey(q, 0.72, 0.04, ref * gain, f"{ref:g} px/frame", labelpos="E", coordinates="axes",
                     fontproperties={"size": 7})  # in the corner the pattern leaves free
        ax.set_aspect("equal")
        ax.set_xlim(min(us) - 0.1 * span, max(us) + 0.1 * span)
        ax.set_ylim(max(vs) + 0.1 * span, min(vs) - 0.1 * span)  # image v grows downwards
        ax.set_xlabel("u (px)", fontsize=8)
        ax.tick_params(labelsize=7)
    axes[0][0].set_ylabel("v (px)", fontsize=8)
    run_title(fig, a.title, fig.get_figwidth())
    save_png(fig, a.out, RUN_FIG_DPI, palette=True)


def correlation(xs, ys):
    """Pearson correlation over the pairs where both are numbers (NaN if undefined)."""
    pairs = [(x, y) for x, y in zip(xs, ys) if not (math.isnan(x) or math.isnan(y))]
    if len(pairs) < 2:
        return math.nan
    mx, my = sum(p[0] for p in pairs) / len(pairs), sum(p[1] for p in pairs) / len(pairs)
    sxy = sum((x - mx) * (y - my) for x, y in pairs)
    sxx, syy = sum((x - mx) ** 2 for x, _ in pairs), sum((y - my) ** 2 for _, y in pairs)
    return sxy / math.sqrt(sxx * syy) if sxx > 0 and syy > 0 else math.nan


def cmd_run_markers(a):
    cols = ["time_s", "internal_disp_px", "external_disp_px", "internal_speed_px_frame", "external_speed_px_frame"]
    rows = read_csv(a.csv, cols)
    events = read_events(a.events)
    plt = pyplot()
    fig, (top, bottom) = plt.subplots(2, 1, figsize=(8, 6.0), sharex=True, layout="constrained")
    t = column(rows, "time_s")
    # Mean displacement and mean speed of each marker set.
    top.plot(t, column(rows, "internal_disp_px"), color="tab:blue", lw=1.2, label="internal pins")
    top.plot(t, column(rows, "external_disp_px"), color="tab:green", lw=1.2, label="external markers")
    top.set_ylabel("mean displacement from first frame (px)")
    si, se = column(rows, "internal_speed_px_frame"), column(rows, "external_speed_px_frame")
    bottom.plot(t, si, color="tab:blue", lw=1.0, label="internal pins")
    bottom.plot(t, se, color="tab:green", lw=1.0, alpha=0.8, label="external markers")
    bottom.set_ylabel("mean speed (px/frame)")
    bottom.set_xlabel("time (s)")
    bottom.set_title(f"correlation of the two mean speeds over the run: {correlation(si, se):.2f}", fontsize=8)
    for ax in (top, bottom):
        mark_events(ax, events)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7, loc="upper left")
    run_title(fig, a.title, fig.get_figwidth())
    save_png(fig, a.out, RUN_FIG_DPI, palette=True)


def cmd_run_indentation(a):
    rows = read_csv(a.csv, ["rest_radius_px", "radial_disp_px", "axial_in_mm", "contact"])
    plt = pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(9, 4.2), layout="constrained")
    groups = [(True, "in contact", "tab:red"), (False, "not in contact", "tab:blue")]
    for ax, col, label in ((axes[0], "radial_disp_px", "radial image displacement (px, + outwards)"),
                           (axes[1], "axial_in_mm", "inward displacement along the camera axis (mm)")):
        # One point per pin, coloured by contact.
        for touching, text, colour in groups:
            sel = [r for r in rows if flag(r["contact"]) == touching]
            if sel:
                ax.scatter(column(sel, "rest_radius_px"), column(sel, col), s=12, color=colour,
                           label=f"{text} ({len(sel)})")
        ax.axhline(0.0, color="0.5", lw=0.8)
        ax.set_xlabel("rest radius in the image (px)")
        ax.set_ylabel(label)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)
    run_title(fig, a.title, fig.get_figwidth())
    save_png(fig, a.out, RUN_FIG_DPI, palette=True)


# ------------------------------------------------------------------ command line

def cmd_check(_):
    pyplot()
    import matplotlib
    print(f"matplotlib {matplotlib.__version__}")


def parser():
    p = argparse.ArgumentParser(prog=PROG, description="Plots of tactip-sim from its CSV files (matplotlib).")
    sub = p.add_subparsers(dest="command", required=True)
    sub.add_parser("check", help="exit 0 when matplotlib imports")

    h = sub.add_parser("heatmap", help="one value per design over 1 or 2 swept keys (a sweep's designs.csv)")
    h.add_argument("csv", help="CSV with one row per design")
    h.add_argument("--x", required=True, metavar="KEY", help="column of the x axis (the last swept key)")
    h.add_argument("--y", default="", metavar="KEY", help="column of the y axis (the first of 2 swept keys)")
    h.add_argument("--value", required=True, metavar="COLUMN", help="column coloured and written in the cells")
    h.add_argument("--title", default="", help="figure title (default: the value column)")
    h.add_argument("--unit", default="", help="unit of the value, shown on the colour bar")
    h.add_argument("--out", required=True, metavar="FILE.png", help="PNG written (atomically)")

    q = sub.add_parser("pareto", help="error against run time, one panel per error column")
    q.add_argument("csv", help="CSV with one row per numerical setting")
    q.add_argument("--x", default="wall_s_per_sim_s", metavar="COLUMN", help="run-time column (log axis)")
    q.add_argument("--y", required=True, metavar="COL[,COL...]", help="error columns, one panel each")
    q.add_argument("--label", default="setting", metavar="COLUMN", help="column naming each setting")
    q.add_argument("--title", default="", help="figure title")
    q.add_argument("--out", default="", metavar="FILE.png", help="PNG written (atomically)")
    q.add_argument("--print-front", action="store_true",
                   help="print each panel's Pareto front: COLUMN<TAB>SETTING<TAB>... (fastest first)")
    for name, what in (("run-motion", "pin displacement and speed over time (motion.csv)"),
                       ("run-quiver", "pin-velocity arrows before, at and after the onset (quiver.csv)"),
                       ("run-markers", "internal pins against external markers over time (markers.csv)"),
                       ("run-indentation", "displacement against rest radius at the deepest press (indentation.csv)")):
        r = sub.add_parser(name, help=what)
        r.add_argument("csv", help="the table `tactip plot` wrote")
        r.add_argument("--events", default="", metavar="EVENTS.csv", help="events.csv: onsets and fall as lines")
        r.add_argument("--title", default="", help="figure title")
        r.add_argument("--out", required=True, metavar="FILE.png", help="PNG written (atomically)")
    return p


RUN_FIGURES = {"run-motion": cmd_run_motion, "run-quiver": cmd_run_quiver, "run-markers": cmd_run_markers,
               "run-indentation": cmd_run_indentation}


def main(argv):
    a = parser().parse_args(argv)
    if a.command == "pareto" and not a.out and not a.print_front:
        print(f"{PROG}: pareto needs --out FILE.png or --print-front", file=sys.stderr)
        return 2
    try:
        {"check": cmd_check, "heatmap": cmd_heatmap, "pareto": cmd_pareto, **RUN_FIGURES}[a.command](a)
    except InputProblem as e:
        print(f"{PROG}: {e}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
