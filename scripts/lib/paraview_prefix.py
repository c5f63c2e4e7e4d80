#!/usr/bin/env python3
"""Build a private ParaView prefix so that find_package(ParaView) works next to Debian's VTK 9.1.

python3-paraview conflicts with python3-vtk9 (both ship vtkmodules), yet paraview-dev's CMake
files reference files that only python3-paraview ships (vtkmodules/*.so, bin/pvpython,
vtk/hierarchy/ParaView). We extract that package without installing it and assemble a prefix:
  PREFIX/lib/<multiarch>/cmake/paraview-5.11   a real copy, so its relative paths resolve in PREFIX
  everything else                              symlinks into /usr or into the extracted package
Directories present in both trees are merged entry by entry; for Python packages the extracted
(ParaView) copy wins. Prints the ParaView_DIR to use. Idempotent.

usage: paraview_prefix.py WORKDIR
"""
import glob
import os
import shutil
import subprocess
import sys


def multiarch():
    try:
        return subprocess.check_output(["dpkg-architecture", "-qDEB_HOST_MULTIARCH"], text=True).strip()
    except (OSError, subprocess.CalledProcessError):
        return "x86_64-linux-gnu"


def extract_package(work):
    extracted = os.path.join(work, "python3-paraview")
    if os.path.isdir(os.path.join(extracted, "usr")):
        return extracted
    debs = glob.glob(os.path.join(work, "python3-paraview_*.deb"))
    if not debs:
        result = subprocess.run(["apt-get", "download", "python3-paraview"], cwd=work,
                                stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        debs = glob.glob(os.path.join(work, "python3-paraview_*.deb"))
        if result.returncode != 0 or not debs:
            sys.exit("paraview_prefix: 'apt-get download python3-paraview' failed: %s" % result.stderr.strip())
    tmp = extracted + ".tmp"
    shutil.rmtree(tmp, ignore_errors=True)
    subprocess.check_call(["dpkg-deb", "-x", debs[0], tmp])
    os.rename(tmp, extracted)
    return extracted


def link_merged(rel, system_root, package_root, prefix, skip):
    """Mirror rel from both roots into prefix: merge shared directories, link the rest."""
    dst = os.path.join(prefix, rel)
    os.makedirs(dst, exist_ok=True)
    sys_dir, pkg_dir = os.path.join(system_root, rel), os.path.join(package_root, rel)
    names = set(os.listdir(sys_dir)) if os.path.isdir(sys_dir) else set()
    names |= set(os.listdir(pkg_dir)) if os.path.isdir(pkg_dir) else set()
    python_packages = rel.startswith("lib/python3/dist-packages")
    for name in sorted(names):
        child = os.path.join(rel, name)
        if child in skip:
            continue
        in_sys, in_pkg = os.path.join(system_root, child), os.path.join(package_root, child)
        both_dirs = os.path.isdir(in_sys) and os.path.isdir(in_pkg) and not os.path.islink(in_pkg)
        if child in skip.get("__merge__", ()) or (both_dirs and not python_packages):
            link_merged(child, system_root, package_root, prefix, skip)
        elif os.path.lexists(in_pkg) and (python_packages or not os.path.lexists(in_sys)):
            os.symlink(in_pkg, os.path.join(dst, name))
        else:
            os.symlink(in_sys, os.path.join(dst, name))


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    work = os.path.abspath(sys.argv[1])
    arch = multiarch()
    cmake_rel = "lib/%s/cmake/paraview-5.11" % arch
    prefix = os.path.join(work, "prefix")
    stamp = os.path.join(work, ".prefix-complete")
    paraview_dir = os.path.join(prefix, cmake_rel)
    if os.path.exists(stamp) and os.path.isdir(paraview_dir):
        print(paraview_dir)
        return
    if not os.path.isdir("/usr/" + cmake_rel):
        sys.exit("paraview_prefix: /usr/%s not found: install paraview-dev" % cmake_rel)
    os.makedirs(work, exist_ok=True)
    package_root = os.path.join(extract_package(work), "usr")
    shutil.rmtree(prefix, ignore_errors=True)
    # The cmake folder is merged so that its paraview-5.11 entry can be a real copy.
    skip = {cmake_rel: True, "__merge__": {"lib", "lib/" + arch, "lib/%s/cmake" % arch}}
    link_merged("", "/usr", package_root, prefix, skip)
    shutil.copytree("/usr/" + cmake_rel, paraview_dir, symlinks=True)
    open(stamp, "w").close()
    print(paraview_dir)


if __name__ == "__main__":
    main()
