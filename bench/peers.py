# The meshers bench/run compares: their Debian packages (installed with apt
# when missing), the command line of each and the conversion of its output
# to a file `partet check` reads. Every tool meshes the same surface, kept
# exactly (TetGen -Y, a Gmsh discrete surface that is not remeshed, Netgen
# through bench/nglib_driver.cpp): `partet check --surface` verifies it.
import json
import os
import shutil
import subprocess

# partet-np2 is partet under `mpirun -np 2`: both cores, as Gmsh gets two
# threads; its peak RSS is the largest rank's. partet-noopt is partet with
# --no-optimize: the rest of the pipeline alone, the ceiling that speeding up
# the optimizer can reach (its meshes are valid, their angles unimproved).
TOOLS = ("tetgen-q", "tetgen", "gmsh-hxt", "gmsh-delaunay", "netgen", "partet", "partet-np2", "partet-noopt")

PACKAGES = {"tetgen-q": ["tetgen"], "tetgen": ["tetgen"], "gmsh-hxt": ["gmsh"], "gmsh-delaunay": ["gmsh"],
            "netgen": ["libnglib-dev", "g++"], "partet": [], "partet-np2": [], "partet-noopt": []}

GMSH_ALGORITHM = {"gmsh-hxt": "10", "gmsh-delaunay": "1"}
TETGEN_SWITCHES = {"tetgen-q": "-pYq1.414", "tetgen": "-pY"}


def installed(package):
    p = subprocess.run(["dpkg-query", "-W", "-f=${Status}", package], capture_output=True, text=True)
    return p.returncode == 0 and p.stdout.strip() == "install ok installed"


def install_packages(tools):
    """apt-get installs the packages the tools need (and GNU time) when missing."""
    wanted = sorted({"time"} | {pkg for t in tools for pkg in PACKAGES[t]})
    missing = [p for p in wanted if not installed(p)]
    if not missing:
        return
    if os.geteuid() != 0:
        raise SystemExit("bench/run: missing packages %s; install them or run as root" % " ".join(missing))
    env = dict(os.environ, DEBIAN_FRONTEND="noninteractive")
    subprocess.run(["apt-get", "update"], check=True, env=env, stdout=subprocess.DEVNULL)
    subprocess.run(["apt-get", "install", "-y"] + missing, check=True, env=env, stdout=subprocess.DEVNULL)


def nglib_paths():
    """(include dir, library dir) of libnglib-dev, from its file list."""
    files = subprocess.run(["dpkg", "-L", "libnglib-dev"], capture_output=True, text=True, check=True).stdout.split()
    header = next(f for f in files if f.endswith("/nglib.h"))
    library = next(f for f in files if f.endswith("/libnglib.so"))
    return os.path.dirname(header), os.path.dirname(library)


def build_nglib_driver(source, work):
    """Compiles bench/nglib_driver.cpp into WORK when missing or older; returns its path."""
    binary = os.path.join(work, "nglib_driver")
    if os.path.exists(binary) and os.path.getmtime(binary) >= os.path.getmtime(source):
        return binary
    include, lib = nglib_paths()
    subprocess.run(["g++", "-O2", "-std=c++17", "-I" + include, source, "-o", binary, "-L" + lib,
                    "-Wl,-rpath," + lib, "-lnglib"], check=True)
    return binary


def prepare(tool, surface, run_dir, partet, nglib_driver):
    """(argv, output file) of one run of TOOL on SURFACE ({"off", "stl"}) in RUN_DIR."""
    if tool in TETGEN_SWITCHES:
        link = os.path.join(run_dir, "in.off")
        if not os.path.exists(link):
            os.symlink(surface["off"], link)
        return ["tetgen", TETGEN_SWITCHES[tool], "-QF", "in.off"], os.path.join(run_dir, "out.mesh")
    if tool in GMSH_ALGORITHM:
        with open(os.path.join(run_dir, "in.geo"), "w") as f:
            f.write('Merge "%s";\nSurface Loop(1) = {1};\nVolume(1) = {1};\n' % surface["stl"])
        return (["gmsh", "in.geo", "-3", "-nt", "2", "-bin", "-format", "msh41", "-setnumber", "Mesh.Algorithm3D",
                 GMSH_ALGORITHM[tool], "-o", "out.msh"], os.path.join(run_dir, "out.msh"))
    if tool == "netgen":
        return [nglib_driver, surface["off"], "out.mesh"], os.path.join(run_dir, "out.mesh")
    ranks = ["mpirun", "--allow-run-as-root", "-np", "2", "--oversubscribe"] if tool == "partet-np2" else []
    options = ["--no-optimize"] if tool == "partet-noopt" else []
    return (ranks + [partet, surface["off"], "-o", "out.vtu", "--report", "report.json", "-q"] + options,
            os.path.join(run_dir, "out.vtu"))


def is_optimization(step):
    """The report's steps that are quality optimization: the optimizer, its
    local restarts and the small meshes' alternatives (meshed again and
    optimized, kept by quality)."""
    return step in ("optimize", "local restarts") or step.endswith(" alternative")


def optimization_cpu(tool, run_dir):
    """(CPU s of the optimization steps, CPU s of all steps) of a partet
    run's report (summed over ranks), or (None, None) for the peers."""
    if not tool.startswith("partet"):
        return None, None
    with open(os.path.join(run_dir, "report.json")) as f:
        steps = json.load(f)["steps"]
    total = sum(sum(s["cpu_s"]) for s in steps)
    return sum(sum(s["cpu_s"]) for s in steps if is_optimization(s["name"])), total


def finish(tool, run_dir):
    """After a successful run: TetGen's .node/.ele become out.mesh (untimed)."""
    if tool in TETGEN_SWITCHES:
        tetgen_to_medit(os.path.join(run_dir, "in.1"), os.path.join(run_dir, "out.mesh"))


def tetgen_to_medit(stem, out_path):
    """STEM.node + STEM.ele -> Medit vertices and tets, which are positive in
    partet's convention as TetGen writes them. (TetGen's own -g output heads
    its Triangles with the count of all faces but lists only the boundary
    ones, which no reader accepts.)"""
    with open(stem + ".node") as nodes, open(stem + ".ele") as eles, open(out_path + ".tmp", "w") as out:
        count = int(nodes.readline().split()[0])
        out.write("MeshVersionFormatted 2\nDimension 3\nVertices\n%d\n" % count)
        shift = 1  # Medit counts from 1, TetGen from its first node's number
        for i in range(count):
            fields = nodes.readline().split()
            shift = 1 - int(fields[0]) if i == 0 else shift
            out.write("%s %s %s 0\n" % tuple(fields[1:4]))
        tets = int(eles.readline().split()[0])
        out.write("Tetrahedra\n%d\n" % tets)
        for _ in range(tets):
            out.write("%d %d %d %d 0\n" % tuple(int(x) + shift for x in eles.readline().split()[1:5]))
        out.write("End\n")
    shutil.move(out_path + ".tmp", out_path)
