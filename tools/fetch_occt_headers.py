#!/usr/bin/python3
"""Supply the OCCT headers that Debian's -dev packages include but do not ship.

Debian's libocct-foundation-dev 7.6.3+dfsg1-7 ships Poly_ArrayOfNodes.hxx, which includes
NCollection_AliasedArray.hxx, a header no package installs: OCCT B-rep code does not compile on a
fresh machine. This script finds every such header (included by an installed header, present in
none), takes it from Debian's own source package of exactly the installed OCCT version, and puts
it into OUT/include, which CMake adds after the system include folder.

The system's apt configuration is left alone: a private sources list, state and cache under OUT
point apt at the same Debian archive the binary package came from, with deb-src entries signed
by Debian's archive keyring. Only the missing headers are extracted; Debian's patches to them
are applied. A stamp makes later runs instant while the installed version stays the same.

Usage: fetch_occt_headers.py --include-dir /usr/include/opencascade --out build/occt-extra core ...
Exit 0 when every header is in place, 1 with one message saying what to install otherwise.
"""

import argparse
import getpass
import glob
import os
import re
import shutil
import subprocess
import sys
import tarfile

DEV_PACKAGE = "libocct-foundation-dev"
DEBIAN_KEYRING = "/usr/share/keyrings/debian-archive-keyring.gpg"
INCLUDE_RE = re.compile(r'^\s*#\s*include\s*[<"]([^>"/]+\.(?:hxx|lxx|gxx))[>"]', re.M)


class Unavailable(Exception):
    """A step cannot be done on this machine; the message says what to install."""


def run(cmd, **kwargs):
    return subprocess.run(cmd, capture_output=True, text=True, **kwargs)


def installed_occt():
    """(source package, source version, binary version) of the installed OCCT -dev package."""
    fmt = "${db:Status-Status} ${source:Package} ${source:Version} ${Version}"
    out = run(["dpkg-query", "-W", "-f", fmt, DEV_PACKAGE])
    fields = out.stdout.split()
    if out.returncode != 0 or len(fields) != 4 or fields[0] != "installed":
        raise Unavailable(
            f"{DEV_PACKAGE} is not installed: run `make deps` (or apt-get install it)"
        )
    return fields[1], fields[2], fields[3]


def included_names(path):
    with open(path, errors="replace") as f:
        return set(INCLUDE_RE.findall(f.read()))


def project_includes(source_dirs, include_dir):
    """The OCCT headers the project's own sources include."""
    names = set()
    for folder in source_dirs:
        for path in glob.glob(os.path.join(folder, "**", "*.[ch]pp"), recursive=True):
            names |= included_names(path)
    return {n for n in names if os.path.exists(os.path.join(include_dir, n))}


def missing_headers(roots, include_dir, extra_dir):
    """Headers reachable from `roots` through #include that neither folder has.

    Conditional includes are followed too: an over-approximation, but a missing header is only
    ever looked for, never invented.
    """
    seen, missing, todo = set(), set(), list(roots)
    while todo:
        name = todo.pop()
        if name in seen:
            continue
        seen.add(name)
        for folder in (include_dir, extra_dir):
            path = os.path.join(folder, name)
            if os.path.exists(path):
                todo.extend(included_names(path))
                break
        else:
            missing.add(name)
    return sorted(missing)


def archive_entries(package, version):
    """deb-src lines for the archives that offer `package` at `version` (from apt's own index)."""
    out = run(["apt-cache", "madison", DEV_PACKAGE])
    entries = []
    for line in out.stdout.splitlines():
        cols = [c.strip() for c in line.split("|")]
        if len(cols) != 3 or cols[1] != version:
            continue
        parts = cols[2].split()
        if len(parts) >= 2 and "/" in parts[1] and parts[0].startswith(("http", "file", "cdrom")):
            suite, component = parts[1].split("/", 1)
            entries.append((parts[0], suite, component))
    if not entries:
        raise Unavailable(
            f"apt knows no Debian archive offering {DEV_PACKAGE} {version}: "
            "run `apt-get update` with Debian's bookworm archive in /etc/apt/sources.list"
        )
    return sorted(set(entries))


def apt_options(root):
    user = getpass.getuser()
    return [
        "-o", f"Dir::Etc::SourceList={root}/sources.list",
        "-o", f"Dir::Etc::SourceParts={root}/sources.list.d",
        "-o", f"Dir::State={root}/state",
        "-o", f"Dir::Cache={root}/cache",
        "-o", "Acquire::Languages=none",
        "-o", f"APT::Sandbox::User={user}",
        "-o", "Debug::NoLocking=true",
    ]  # fmt: skip


def download_source(root, package, version, entries):
    """apt-get source --download-only into root/download; returns the .dsc path."""
    for sub in ("sources.list.d", "state/lists/partial", "cache/archives/partial", "download"):
        os.makedirs(os.path.join(root, sub), exist_ok=True)
    signed = f" [signed-by={DEBIAN_KEYRING}]" if os.path.exists(DEBIAN_KEYRING) else ""
    with open(os.path.join(root, "sources.list"), "w") as f:
        f.write("# Written by tools/fetch_occt_headers.py: Debian sources of the installed OCCT\n")
        for uri, suite, component in entries:
            f.write(f"deb-src{signed} {uri} {suite} {component}\n")
    opts = apt_options(root)
    upd = run(["apt-get", *opts, "update"])
    indexes = glob.glob(os.path.join(root, "state", "lists", "*_Sources*"))
    if upd.returncode != 0 or not indexes:
        raise Unavailable(
            "cannot read Debian's source index (apt-get update with a private deb-src list "
            f"failed: {first_problem(upd.stderr)}); this machine needs access to Debian's archive "
            f"({entries[0][0]})"
        )
    download = os.path.join(root, "download")
    src = run(["apt-get", *opts, "source", "--download-only", f"{package}={version}"], cwd=download)
    dsc = os.path.join(download, f"{package}_{strip_epoch(version)}.dsc")
    if (
        src.returncode != 0
        and os.path.exists(dsc)
        and glob.glob(os.path.join(download, "*.orig.tar.*"))
    ):
        # Debian 13's mirror here serves the .dsc and the upstream tarball (apt checked both
        # against the index) but not always Debian's packaging tarball: the headers are taken
        # as upstream wrote them, and supply() says that Debian's patches went unread.
        print(f"note: only part of {package} {version} downloaded ({last_line(src.stderr)})")
        return dsc
    if src.returncode != 0 or not os.path.exists(dsc):
        raise Unavailable(
            f"Debian's archive has no source package {package}={version} "
            f"({last_line(src.stderr)}); install the {DEV_PACKAGE} version the archive offers "
            "(apt-get update && apt-get install --only-upgrade " + DEV_PACKAGE + ")"
        )
    return dsc


def strip_epoch(version):
    return version.split(":", 1)[1] if ":" in version else version


def first_problem(text):
    """apt's first error or warning line: the cause, not the summary."""
    lines = [l for l in text.splitlines() if l.startswith(("E:", "W:"))]
    return lines[0] if lines else last_line(text)


def last_line(text):
    lines = [l for l in text.strip().splitlines() if l.strip()]
    return lines[-1] if lines else "no output"


def dsc_fields(dsc):
    """Version and file names listed by a .dsc (apt has checked their hashes on download)."""
    version, files, section = None, [], None
    with open(dsc, errors="replace") as f:
        for line in f:
            if line.startswith("Version:"):
                version = line.split(":", 1)[1].strip()
            if re.match(r"^[A-Za-z-]+:", line):
                section = line.split(":", 1)[0]
            elif section == "Files" and line.startswith(" "):
                files.append(line.split()[-1])
    return version, files


def extract_headers(orig, names, dest):
    """Take src/<Package>/<name> for each wanted name out of the upstream tarball."""
    found = {}
    with tarfile.open(orig) as tar:
        for member in tar:
            base = os.path.basename(member.name)
            if member.isfile() and base in names and "/src/" in "/" + member.name:
                data = tar.extractfile(member).read()
                found[base] = (member.name.split("/", 1)[1], data)
    for base, (_, data) in found.items():
        with open(os.path.join(dest, base), "wb") as f:
            f.write(data)
    return {base: path for base, (path, _) in found.items()}


def debian_patches(debian_tar):
    """Debian's quilt patches in series order, as (name, text)."""
    with tarfile.open(debian_tar) as tar:
        members = {m.name: m for m in tar if m.isfile()}
        series = members.get("debian/patches/series")
        if series is None:
            return []
        order = [
            l.split()[0]
            for l in tar.extractfile(series).read().decode().splitlines()
            if l.strip() and not l.startswith("#")
        ]
        patches = []
        for name in order:
            member = members.get("debian/patches/" + name)
            if member is not None:
                patches.append((name, tar.extractfile(member).read().decode(errors="replace")))
        return patches


def file_sections(patch_text):
    """Split a patch into per-file sections: {path after a/ or b/: section text}."""
    sections, current, lines = {}, None, []
    for line in patch_text.splitlines(keepends=True):
        if line.startswith("--- "):
            if current:
                sections[current] = "".join(lines)
            current, lines = None, [line]
            continue
        if line.startswith("+++ ") and lines and lines[0].startswith("--- "):
            path = line[4:].split("\t")[0].strip()
            current = path.split("/", 1)[1] if "/" in path else path
        if lines:
            lines.append(line)
    if current:
        sections[current] = "".join(lines)
    return sections


def apply_debian_patches(debian_tar, sources, dest):
    """Apply the hunks of Debian's patches that touch the extracted headers."""
    applied = []
    for name, text in debian_patches(debian_tar):
        for path, section in file_sections(text).items():
            base = os.path.basename(path)
            if sources.get(base) != path:
                continue
            if shutil.which("patch") is None:
                raise Unavailable(f"Debian patch {name} changes {base}: install `patch`")
            res = run(["patch", "-s", os.path.join(dest, base)], input=section)
            if res.returncode != 0:
                raise Unavailable(f"Debian patch {name} does not apply to {base}: {res.stdout}")
            applied.append(f"{name}:{base}")
    return applied


def read_stamp(path):
    """(package version line, names looked for) recorded by the last successful run."""
    try:
        with open(path) as f:
            lines = f.read().splitlines()
    except OSError:
        return None, set()
    looked_for = {l.split()[1] for l in lines[1:] if l.startswith(("supplied ", "absent "))}
    return (lines[0] if lines else None), looked_for


def supply(roots, include_dir, out):
    """Put every missing header into out/include; returns (supplied, absent upstream)."""
    package, version, binary_version = installed_occt()
    dest = os.path.join(out, "include")
    stamp_path = os.path.join(out, "SOURCE")
    stamped_version, looked_for = read_stamp(stamp_path)
    if stamped_version != f"{package} {version}":
        shutil.rmtree(dest, ignore_errors=True)  # another OCCT version: its headers do not apply
        looked_for = set()
    missing = missing_headers(roots, include_dir, dest)
    if not set(missing) - looked_for:
        return [], missing
    if binary_version != version:
        print(f"note: {DEV_PACKAGE} {binary_version} was built from {package} {version}")
    root = os.path.join(out, "apt")
    dsc = download_source(root, package, version, archive_entries(package, version))
    dsc_version, files = dsc_fields(dsc)
    if dsc_version != version:
        raise Unavailable(
            f"the source package is {package} {dsc_version} but {DEV_PACKAGE} {version} is "
            "installed: upgrade it to the archive's version (apt-get install " + DEV_PACKAGE + ")"
        )
    download = os.path.dirname(dsc)
    orig = [f for f in files if ".orig.tar." in f]
    debian = [f for f in files if ".debian.tar." in f]
    if len(orig) != 1:
        raise Unavailable(f"{os.path.basename(dsc)} lists no single upstream tarball: {files}")
    os.makedirs(dest, exist_ok=True)
    supplied, absent = {}, set()
    while missing:  # a supplied header may include another missing one
        got = extract_headers(os.path.join(download, orig[0]), set(missing), dest)
        supplied.update(got)
        absent |= set(missing) - set(got)
        missing = [n for n in missing_headers(roots, include_dir, dest) if n not in absent]
    if not supplied:
        raise Unavailable(f"{package} {version} has none of {', '.join(sorted(absent))}")
    patched = []
    if debian and os.path.exists(os.path.join(download, debian[0])):
        patched = apply_debian_patches(os.path.join(download, debian[0]), supplied, dest)
    elif debian:
        patched = ["unread: Debian's packaging tarball was not downloadable"]
        print(f"note: {', '.join(sorted(supplied))} as upstream wrote them ({debian[0]} missing)")
    with open(stamp_path, "w") as f:
        f.write(f"{package} {version}\n")
        f.writelines(f"supplied {b} {supplied[b]}\n" for b in sorted(supplied))
        f.writelines(f"absent {b}\n" for b in sorted(absent))
        f.writelines(f"patched {p}\n" for p in patched)
    for name in files:  # the upstream tarball is large: keep only what the build uses
        path = os.path.join(download, name)
        if os.path.exists(path):
            os.remove(path)
    return sorted(supplied), sorted(absent)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--include-dir", required=True, help="OCCT's system include folder")
    parser.add_argument("--out", required=True, help="build-local folder for the headers")
    parser.add_argument(
        "sources", nargs="+", help="the project's source folders, whose OCCT includes count"
    )
    args = parser.parse_args()
    out = os.path.abspath(args.out)
    try:
        if not os.path.isfile(os.path.join(args.include_dir, "Standard.hxx")):
            raise Unavailable(f"no OCCT headers in {args.include_dir}: install {DEV_PACKAGE}")
        roots = project_includes(args.sources, args.include_dir)
        supplied, absent = supply(roots, args.include_dir, out)
    except Unavailable as err:
        print(f"PopUp cannot build its OCCT code here: {err}", file=sys.stderr)
        return 1
    if supplied:
        print(
            f"OCCT headers from Debian's source package into {out}/include: {', '.join(supplied)}"
        )
    if absent:
        print(f"note: included by OCCT, in no package and not in its source: {', '.join(absent)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
