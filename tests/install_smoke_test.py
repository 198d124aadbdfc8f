"""The install works like a desktop program's: `cmake --install` into a temporary prefix, the
prefix moved elsewhere (so nothing can lean on the paths it was installed to), and the installed
programs run from an unrelated folder find their data beside themselves.

    python3 install_smoke_test.py CMAKE BUILD_DIR WITH_STUDIO(0|1)

Checks: the layout (programs, example, translations, icons, desktop entry, man pages, docs),
the desktop entry against desktop-file-validate (when installed), the man pages hold the
programs' --help text, `inlay-cli demo` renders from the moved prefix, the studio takes its
screenshot there (offscreen), and the example it reads is the installed one: with the installed
photo removed, demo fails naming the installed file (not a source-tree copy).
"""
import gzip
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from checks import check, summary  # noqa: E402

EXPECTED = [
    "bin/inlay-cli",
    "share/inlay/example/scene.json",
    "share/inlay/example/photo.png",
    "share/icons/hicolor/scalable/apps/inlay.svg",
    "share/icons/hicolor/256x256/apps/inlay.png",
    "share/icons/hicolor/48x48/apps/inlay.png",
    "share/man/man1/inlay-cli.1.gz",
    "share/doc/inlay/README.md",
    "share/doc/inlay/docs/scene-file.md",
    "share/doc/inlay/docs/images/before_after.png",
    "share/doc/inlay/copyright",
    "share/doc/inlay/changelog.gz",
]
EXPECTED_STUDIO = [
    "bin/inlay",
    "share/applications/inlay.desktop",
    "share/inlay/translations/inlay_de.qm",
    "share/inlay/translations/inlay_fr.qm",
    "share/man/man1/inlay.1.gz",
]


def clean_env():
    """The environment without the overrides that would point the programs at other data."""
    env = {k: v for k, v in os.environ.items()
           if k not in ("INLAY_DATA_DIR", "INLAY_EXAMPLE_DIR", "INLAY_SOURCE_DIR")}
    env["QT_QPA_PLATFORM"] = "offscreen"
    return env


def run(cmd, cwd, timeout=600):
    return subprocess.run(cmd, cwd=cwd, env=clean_env(), capture_output=True, text=True,
                          timeout=timeout)


def check_layout(prefix, studio):
    for rel in EXPECTED + (EXPECTED_STUDIO if studio else []):
        check("installed " + rel, os.path.isfile(os.path.join(prefix, rel)))
    check("inlay-cli is executable", os.access(os.path.join(prefix, "bin/inlay-cli"), os.X_OK))


def check_desktop_entry(prefix):
    validate = shutil.which("desktop-file-validate")
    entry = os.path.join(prefix, "share/applications/inlay.desktop")
    if not validate:
        print("note: desktop-file-validate not installed (Debian: desktop-file-utils); not run")
        return
    r = run([validate, entry], cwd=prefix)
    check("desktop-file-validate inlay.desktop", r.returncode == 0 and not r.stdout.strip(),
          r.stdout + r.stderr)


def check_man_page(prefix, program, help_text):
    with gzip.open(os.path.join(prefix, "share/man/man1", program + ".1.gz"), "rt") as f:
        page = f.read()
    check(program + ".1 has a title line", '.TH "' + program.upper() + '" "1"' in page)
    # Every option of --help appears in the page (groff escapes '-' as '\-').
    flags = sorted({w.strip(",") for w in help_text.split() if w.startswith("--")})
    missing = [f for f in flags if f.replace("-", "\\-") not in page]
    check(program + ".1 holds every flag of --help", flags and not missing, str(missing))


def check_programs(prefix, studio, work):
    cli = os.path.join(prefix, "bin/inlay-cli")
    r = run([cli, "--help"], cwd=work)
    check("installed inlay-cli --help", r.returncode == 0 and "demo" in r.stdout, r.stderr)
    check_man_page(prefix, "inlay-cli", r.stdout)
    r = run([cli, "demo", "-o", "demo.png", "--spp", "2", "--quiet"], cwd=work)
    check("installed inlay-cli demo from another folder", r.returncode == 0 and
          os.path.getsize(os.path.join(work, "demo.png")) > 1000, r.stderr)
    if studio:
        r = run([os.path.join(prefix, "bin/inlay"), "--screenshot", "shot.png", "--wait-spp", "1"],
                cwd=work)
        check("installed studio --screenshot (offscreen)", r.returncode == 0 and
              os.path.getsize(os.path.join(work, "shot.png")) > 1000, r.stderr)
    # The example read is the installed one: without its photo, demo names the installed file.
    photo = os.path.join(prefix, "share/inlay/example/photo.png")
    os.remove(photo)
    r = run([cli, "demo", "-o", "none.png", "--spp", "1", "--quiet"], cwd=work)
    check("demo reads the installed example", r.returncode == 2 and
          os.path.realpath(photo) in r.stderr and not os.path.exists(os.path.join(work, "none.png")),
          "exit %d: %s" % (r.returncode, r.stderr.strip()))


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    cmake, build_dir, studio = sys.argv[1], sys.argv[2], sys.argv[3] not in ("0", "", "OFF")
    with tempfile.TemporaryDirectory(prefix="inlay-install-") as tmp:
        first = os.path.join(tmp, "installed-here")
        r = subprocess.run([cmake, "--install", build_dir, "--prefix", first],
                           capture_output=True, text=True, timeout=600)
        if not check("cmake --install", r.returncode == 0, r.stdout[-2000:] + r.stderr):
            return summary()
        prefix = os.path.join(tmp, "moved", "elsewhere")   # relocated after the install
        os.makedirs(os.path.dirname(prefix))
        shutil.move(first, prefix)
        work = os.path.join(tmp, "work")
        os.makedirs(work)
        check_layout(prefix, studio)
        if studio:
            check_desktop_entry(prefix)
        check_programs(prefix, studio, work)
    return summary()


if __name__ == "__main__":
    sys.exit(main())
