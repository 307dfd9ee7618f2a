# bench/run's output: one row per (input, tool), written as table.json and
# as table.md with a summary (median tets/s per tool, partet's median
# per-input ratios against TetGen -pYq1.414 and Gmsh HXT) and the quality
# comparison of issue 5 (partet against the best peer, next to the bound
# the input's own dihedral angles force) with partet's optimization share
# of its CPU time.
import json
import statistics

COLUMNS = [("tool", "tool", "s"), ("input", "input", "s"), ("triangles", "triangles", "d"),
           ("tets", "tets", "d"), ("wall_s", "wall s", ".2f"), ("tets_per_s", "tets/s", ".0f"),
           ("peak_rss_mb", "peak RSS MB", ".0f"), ("bytes_per_tet", "bytes/tet", ".0f"),
           ("min_dihedral_deg", "min dihedral deg", ".3g"), ("pct_under_10", "% tets < 10 deg", ".2f"),
           ("radius_ratio_mean", "mean radius ratio", ".3f"), ("optimization_share", "opt share", ".2f"),
           ("valid", "valid", "s")]

# Speeds on smaller inputs measure process start-up (Gmsh's is ~0.2 s).
MIN_TRIANGLES = 1000


def cell(value, fmt):
    if value is None:
        return ""
    if isinstance(value, bool):
        return "yes" if value else "no"
    return format(value, fmt)


def good(row):
    return row["status"] == "ok" and row["valid"]


def rate_summary(rows, tools):
    """Per tool: median over inputs of tets/s (good runs on inputs of
    MIN_TRIANGLES or more only)."""
    lines = ["| tool | inputs meshed validly | median tets/s (inputs of %d+ triangles) |" % MIN_TRIANGLES,
             "|---|---:|---:|"]
    for tool in tools:
        rates = [r["tets_per_s"] for r in rows if r["tool"] == tool and good(r) and r["triangles"] >= MIN_TRIANGLES]
        median = format(statistics.median(rates), ".0f") if rates else ""
        valid = sum(r["tool"] == tool and good(r) for r in rows)
        lines.append("| %s | %d of %d | %s |" % (tool, valid, sum(r["tool"] == tool for r in rows), median))
    return lines


# partet run otherwise (bench/peers.py), each against the peers and partet.
PARTET_VARIANTS = (("partet-np2", "partet on 2 ranks (both cores) against the peers and one rank"),
                   ("partet-noopt", "partet without its optimizer (--no-optimize) against the peers and partet"))


def ratio_summary(rows, mine, peers):
    """MINE / peer per input where both are good (inputs of MIN_TRIANGLES
    or more), median over inputs."""
    by_key = {(r["input"], r["tool"]): r for r in rows}
    lines = ["| %s vs | inputs of %d+ triangles | median speed ratio (tets/s) | median memory ratio (bytes/tet) |"
             % (mine, MIN_TRIANGLES), "|---|---:|---:|---:|"]
    for peer in peers:
        pairs = [(r, by_key.get((r["input"], peer))) for r in rows if r["tool"] == mine and good(r)]
        pairs = [(p, q) for p, q in pairs if q and good(q) and p["triangles"] >= MIN_TRIANGLES]
        if not pairs:
            continue
        speed = statistics.median(p["tets_per_s"] / q["tets_per_s"] for p, q in pairs)
        memory = statistics.median(p["bytes_per_tet"] / q["bytes_per_tet"] for p, q in pairs)
        lines.append("| %s | %d | %.3g | %.3g |" % (peer, len(pairs), speed, memory))
    return lines


def optimization_share(row):
    """The optimization steps' share of a partet run's CPU time (its report;
    None for the peers and for rows stored before it was recorded)."""
    opt, total = row.get("optimization_cpu_s"), row.get("cpu_s")
    return opt / total if opt is not None and total else None


def share_summary(rows, tools):
    """Issue 5 asks the optimization to take at most a third of the meshing
    time: per partet tool, the median share over inputs and the share of
    the summed CPU, over all inputs and over those of MIN_TRIANGLES+."""
    lines = ["| tool | inputs | median share | share of the summed CPU | inputs of %d+ triangles | median share |"
             " share of the summed CPU |" % MIN_TRIANGLES, "|---|---:|---:|---:|---:|---:|---:|"]
    for tool in tools:
        mine = [r for r in rows if r["tool"] == tool and good(r) and optimization_share(r) is not None]
        if not mine:
            continue
        cells = []
        for subset in (mine, [r for r in mine if r["triangles"] >= MIN_TRIANGLES]):
            if not subset:
                cells += ["0", "", ""]
                continue
            summed = sum(r["optimization_cpu_s"] for r in subset) / sum(r["cpu_s"] for r in subset)
            cells += [str(len(subset)), format(statistics.median(optimization_share(r) for r in subset), ".3f"),
                      format(summed, ".3f")]
        lines.append("| %s | %s |" % (tool, " | ".join(cells)))
    return lines


def quality_comparison(rows, forced):
    """Issue 5: partet's worst angles next to the best peer's and the input's bound."""
    lines = ["| input | forced by input: min surface dihedral deg | partet min dihedral deg | best peer min dihedral deg"
             " | partet % < 10 deg | best peer % < 10 deg |", "|---|---:|---:|---:|---:|---:|"]
    for name in sorted({r["input"] for r in rows}, key=input_order):
        mine = [r for r in rows if r["input"] == name and r["tool"] == "partet" and good(r)]
        peers = [r for r in rows if r["input"] == name and not r["tool"].startswith("partet") and good(r)]
        best_min = max((r["min_dihedral_deg"] for r in peers), default=None)
        best_pct = min((r["pct_under_10"] for r in peers), default=None)
        lines.append("| %s | %s | %s | %s | %s | %s |" % (
            name, cell(forced.get(name), ".3g"), cell(mine[0]["min_dihedral_deg"] if mine else None, ".3g"),
            cell(best_min, ".3g"), cell(mine[0]["pct_under_10"] if mine else None, ".2f"), cell(best_pct, ".2f")))
    return lines


def input_order(name):
    base, _, rounds = name.rpartition(" r")
    return (base, int(rounds)) if rounds.isdigit() else (name, 0)


def write(rows, forced, tools, out_dir, header):
    rows = sorted(rows, key=lambda r: (input_order(r["input"]), tools.index(r["tool"])))
    with open(out_dir + "/table.json", "w") as f:
        json.dump({"rows": rows, "forced_min_dihedral_deg": forced}, f, indent=1, sort_keys=True)
    lines = [header, "", "| " + " | ".join(title for _, title, _ in COLUMNS) + " | status |",
             "|" + "---|" * 2 + "---:|" * (len(COLUMNS) - 3) + "---|---|"]
    for r in rows:
        note = r["status"] + (": " + r["error"].replace("|", "/").replace("\n", " ") if r["error"] else "")
        values = dict(r, optimization_share=optimization_share(r))
        lines.append("| " + " | ".join(cell(values.get(key), fmt) for key, _, fmt in COLUMNS) + " | " + note + " |")
    lines += ["", "### Speed per tool", ""] + rate_summary(rows, tools)
    lines += ["", "### partet against the peers", ""] + ratio_summary(rows, "partet", [t for t in ("tetgen-q", "gmsh-hxt")
                                                                                        if t in tools])
    for variant, title in PARTET_VARIANTS:
        if variant in tools:
            lines += ["", "### " + title, ""] + ratio_summary(
                rows, variant, [t for t in ("tetgen-q", "gmsh-hxt", "partet") if t in tools])
    lines += ["", "### Worst angles (issue 5)", ""] + quality_comparison(rows, forced)
    lines += ["", "### Optimization's share of partet's CPU time (issue 5: at most a third)", "",
              "The optimizer, its local restarts and the small meshes' alternatives, from each run's report "
              "(the last of its runs; summed over ranks).", ""]
    lines += share_summary(rows, [t for t in tools if t.startswith("partet") and t != "partet-noopt"])
    with open(out_dir + "/table.md", "w") as f:
        f.write("\n".join(lines) + "\n")
