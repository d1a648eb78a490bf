"""The fresh-machine build helpers: OCCT headers from Debian's source, the unpackaged-file check.

Inputs are built here by hand (include folders, tarballs, dpkg listings), so every expected value
comes from the test, not from the code under test.
"""

import importlib.util
import io
import os
import shutil
import subprocess
import tarfile

import pytest

from conftest import SOURCE_DIR, BUILD_DIR


def load_tool(name):
    spec = importlib.util.spec_from_file_location(
        name, os.path.join(SOURCE_DIR, "tools", name + ".py")
    )
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


fetch = load_tool("fetch_occt_headers")
check = load_tool("check_unpackaged_deps")


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def make_tar(path, files):
    with tarfile.open(path, "w:xz") as tar:
        for name, text in files.items():
            data = text.encode()
            info = tarfile.TarInfo(name)
            info.size = len(data)
            tar.addfile(info, io.BytesIO(data))


def test_missing_headers_follow_includes_from_the_project_only(tmp_path):
    inc, extra, src = tmp_path / "inc", tmp_path / "extra", tmp_path / "src"
    write(str(inc / "A.hxx"), '#include <B.hxx>\n#include "Std.hxx"\n')
    write(str(inc / "B.hxx"), "#include <Gone.hxx>\n  #  include <Supplied.hxx>\n")
    write(str(inc / "Std.hxx"), "// nothing\n")
    write(str(inc / "Unused.hxx"), "#include <AlsoGone.hxx>\n")  # never reached: not missing
    write(str(extra / "Supplied.hxx"), "#include <Deeper.hxx>\n")
    write(str(src / "core.cpp"), "#include <A.hxx>\n#include <vector>\n#include <NotOcct.hxx>\n")
    roots = fetch.project_includes([str(src)], str(inc))
    assert roots == {"A.hxx"}
    assert fetch.missing_headers(roots, str(inc), str(extra)) == ["Deeper.hxx", "Gone.hxx"]


def test_only_the_missing_headers_come_out_of_the_upstream_tarball(tmp_path):
    orig = tmp_path / "occt.orig.tar.xz"
    make_tar(
        str(orig),
        {
            "occt-7.6.3/src/NCollection/Gone.hxx": "gone v1\n",
            "occt-7.6.3/src/Other/Present.hxx": "present\n",
            "occt-7.6.3/tests/Gone.hxx": "a test copy, not a header\n",
        },
    )
    dest = tmp_path / "include"
    dest.mkdir()
    got = fetch.extract_headers(str(orig), {"Gone.hxx", "Absent.hxx"}, str(dest))
    assert got == {"Gone.hxx": "src/NCollection/Gone.hxx"}
    assert sorted(os.listdir(dest)) == ["Gone.hxx"]
    assert (dest / "Gone.hxx").read_text() == "gone v1\n"


@pytest.mark.skipif(shutil.which("patch") is None, reason="needs patch(1)")
def test_debian_patches_touch_only_the_extracted_headers(tmp_path):
    patch = (
        "Description: two files\n"
        "--- a/src/NCollection/Gone.hxx\n"
        "+++ b/src/NCollection/Gone.hxx\n"
        "@@ -1 +1 @@\n"
        "-gone v1\n"
        "+gone v2\n"
        "--- a/src/Elsewhere/Other.cxx\n"
        "+++ b/src/Elsewhere/Other.cxx\n"
        "@@ -1 +1 @@\n"
        "-x\n"
        "+y\n"
    )
    debian = tmp_path / "occt.debian.tar.xz"
    make_tar(
        str(debian),
        {
            "debian/patches/series": "# comment\nfix-gone.patch\nmissing.patch\n",
            "debian/patches/fix-gone.patch": patch,
        },
    )
    dest = tmp_path / "include"
    write(str(dest / "Gone.hxx"), "gone v1\n")
    applied = fetch.apply_debian_patches(
        str(debian), {"Gone.hxx": "src/NCollection/Gone.hxx"}, str(dest)
    )
    assert applied == ["fix-gone.patch:Gone.hxx"]
    assert (dest / "Gone.hxx").read_text() == "gone v2\n"
    assert sorted(os.listdir(dest)) == ["Gone.hxx"]


def test_dsc_names_its_version_and_files(tmp_path):
    dsc = tmp_path / "opencascade_7.6.3+dfsg1-7.dsc"
    dsc.write_text(
        "Format: 3.0 (quilt)\nSource: opencascade\nVersion: 7.6.3+dfsg1-7\n"
        "Checksums-Sha256:\n abc 10 opencascade_7.6.3+dfsg1.orig.tar.xz\n"
        "Files:\n 111 10 opencascade_7.6.3+dfsg1.orig.tar.xz\n"
        " 222 20 opencascade_7.6.3+dfsg1-7.debian.tar.xz\n"
    )
    version, files = fetch.dsc_fields(str(dsc))
    assert version == "7.6.3+dfsg1-7"
    assert files == [
        "opencascade_7.6.3+dfsg1.orig.tar.xz",
        "opencascade_7.6.3+dfsg1-7.debian.tar.xz",
    ]


def test_the_build_has_no_opencascade_header_outside_packages_and_build():
    """The header Debian 12 and 13 lack is used from build/occt-extra, never from /usr; where
    OCCT's package ships it (7.9, Debian sid), the build takes it from there and supplies none."""
    used = check.depfile_paths(BUILD_DIR)[1]
    assert "/usr/include/opencascade/Poly_ArrayOfNodes.hxx" in used
    shipped = "/usr/include/opencascade/NCollection_AliasedArray.hxx"
    if os.path.exists(shipped):
        assert shipped in used
        assert not os.path.exists(os.path.join(BUILD_DIR, "occt-extra", "SOURCE"))
        return
    extra = os.path.join(BUILD_DIR, "occt-extra", "include", "NCollection_AliasedArray.hxx")
    with open(extra) as f:
        assert "class NCollection_AliasedArray" in f.read()
    with open(os.path.join(BUILD_DIR, "occt-extra", "SOURCE")) as f:
        stamp = f.read().splitlines()
    installed = subprocess.run(
        ["dpkg-query", "-W", "-f=${source:Package} ${source:Version}", "libocct-foundation-dev"],
        capture_output=True,
        text=True,
    ).stdout
    assert stamp[0] == installed  # the headers of exactly the installed OCCT
    assert (
        "supplied NCollection_AliasedArray.hxx src/NCollection/NCollection_AliasedArray.hxx"
        in stamp
    )


def fake_build(tmp_path, used_headers):
    build = tmp_path / "build"
    write(
        str(build / "CMakeFiles" / "x.dir" / "x.cpp.o.d"),
        "x.o: /src/x.cpp \\\n " + " \\\n ".join(used_headers) + "\n",
    )
    shutil.copy("/bin/true", str(build / "true"))
    return build


def fake_dpkg(tmp_path, monkeypatch, owned):
    info = tmp_path / "dpkg"
    write(str(info / "libc6-dev:amd64.list"), "\n".join(owned) + "\n")
    monkeypatch.setattr(check, "DPKG_INFO", str(info))


def run_check(monkeypatch, build, ci):
    monkeypatch.setenv("CI", "true" if ci else "")
    monkeypatch.setattr("sys.argv", ["check", str(build), "--pythonpath", os.environ["PYTHONPATH"]])
    return check.main()


def test_an_unpackaged_header_fails_in_ci_and_warns_outside(tmp_path, monkeypatch, capsys):
    build = fake_build(tmp_path, ["/usr/include/stdio.h", "/usr/include/string.h"])
    # Everything the probe and /bin/true load counts as packaged, except string.h.
    _, _, everything, problems = check.collect(str(build), os.environ["PYTHONPATH"])
    assert problems == []
    fake_dpkg(tmp_path, monkeypatch, sorted(everything - {"/usr/include/string.h"}))
    assert run_check(monkeypatch, build, ci=True) == 1
    out = capsys.readouterr().out
    assert "unpackaged-deps error: 1 file(s)" in out
    assert "  /usr/include/string.h\n" in out and "stdio.h" not in out
    assert run_check(monkeypatch, build, ci=False) == 0
    assert "unpackaged-deps warning: 1 file(s)" in capsys.readouterr().out


def test_merged_usr_spellings_count_as_packaged(tmp_path, monkeypatch):
    libc = "/lib/x86_64-linux-gnu/libc.so.6"
    if not os.path.exists(libc):
        pytest.skip("no x86_64 libc")
    fake_dpkg(tmp_path, monkeypatch, ["/usr" + libc])
    assert check.is_packaged(libc, check.packaged_files())
    assert not check.is_packaged("/usr/include/stdio.h", check.packaged_files())


def test_an_empty_build_cannot_pass(tmp_path, monkeypatch, capsys):
    (tmp_path / "empty").mkdir()
    assert run_check(monkeypatch, tmp_path / "empty", ci=False) == 1
    assert "no compiler dependency files" in capsys.readouterr().out
