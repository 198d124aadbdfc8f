#!/usr/bin/python3
"""inlay-cli's contract (../shared/spec/cli.md) on the bundled example: usage, exit status, bad
input named by file and key, atomic outputs, progress CSV, layers, Ctrl-C. Needs nothing from
../shared.

usage: cli_badinput_test.py INLAY_CLI
"""
import json, os, shutil, signal, subprocess, sys, tempfile, threading, time

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLE = os.path.join(HERE, "..", "resources", "example")
from checks import check, summary  # noqa: E402


def run(cli, *args, timeout=300):
    return subprocess.run([cli, *args], capture_output=True, text=True, timeout=timeout)


def check_replace_radiance(cli, scene, plain_png, tmp):
    """--replace-radiance (diagnostics): the bounces off the photo's clipped pixels read the file's
    radiance, so the composite changes (the scene as `plain_png` rendered it, 4 samples, seed 1);
    a file missing or of another size exits 2 naming the file and the flag."""
    import numpy as np
    import OpenImageIO as oiio
    import cv2
    bright, small, out = (os.path.join(tmp, n) for n in ("radiance50.exr", "small.exr", "replaced.png"))
    h, w = cv2.imread(plain_png).shape[:2]
    oiio.ImageBuf(np.full((h, w, 3), 50, np.float32)).write(bright)
    oiio.ImageBuf(np.full((10, 12, 3), 50, np.float32)).write(small)
    again = os.path.join(tmp, "again.png")
    run(cli, "render", scene, "-o", again, "--spp", "4", "--seed", "1", "--quiet")
    r = run(cli, "render", scene, "-o", out, "--spp", "4", "--seed", "1", "--quiet", "--replace-radiance", bright)
    changed = int((cv2.imread(out) != cv2.imread(again)).any(axis=2).sum()) if r.returncode == 0 else 0
    check("--replace-radiance changes the bounces", r.returncode == 0 and changed > 20, "%d pixels; %s" % (changed, r.stderr))
    for f, why in ((small, "not the photo's size"), (os.path.join(tmp, "none.exr"), "none.exr")):
        r = run(cli, "render", scene, "-o", out, "--spp", "1", "--quiet", "--replace-radiance", f)
        check("--replace-radiance " + why, r.returncode == 2 and "--replace-radiance" in r.stderr and why in r.stderr,
              r.stderr)


def main():
    cli = os.path.abspath(sys.argv[1])
    tmp = tempfile.mkdtemp(prefix="inlay_cli_")
    base = json.load(open(os.path.join(EXAMPLE, "scene.json")))
    photo = os.path.abspath(os.path.join(EXAMPLE, "photo.png"))

    def scene(mutate, name):
        s = json.loads(json.dumps(base))
        s["photo"] = photo
        mutate(s)
        p = os.path.join(tmp, name + ".json")
        with open(p, "w") as f:
            json.dump(s, f)
        return p

    r = run(cli, "--help")
    check("help", r.returncode == 0 and "render" in r.stdout and "Exit status" in r.stdout, r.stderr)
    check("help names --no-grain", "--no-grain" in r.stdout, r.stdout)
    check("help names --no-response-check", "--no-response-check" in r.stdout, r.stdout)
    r = run(cli, "--version")
    check("version", r.returncode == 0 and r.stdout.startswith("inlay-cli "), r.stdout)
    check("no args", run(cli).returncode == 2)
    r = run(cli, "frobnicate")
    check("unknown command", r.returncode == 2 and "frobnicate" in r.stderr, r.stderr)
    r = run(cli, "render", "x.json", "--spp", "-3", "-o", "a.png")
    check("bad flag value", r.returncode == 2 and "--spp" in r.stderr, r.stderr)
    for v in ("-0.1", "1.5", "nan", "low"):
        r = run(cli, "render", "x.json", "--noise", v, "-o", "a.png")
        check("bad --noise " + v, r.returncode == 2 and "--noise" in r.stderr, r.stderr)
    for v in ("-1", "nan", "inf", "bright"):
        r = run(cli, "render", "x.json", "--clamp-indirect", v, "-o", "a.png")
        check("bad --clamp-indirect " + v, r.returncode == 2 and "--clamp-indirect" in r.stderr, r.stderr)
    check("help names --clamp-indirect", "--clamp-indirect" in run(cli, "--help").stdout)
    for flag, values in (("--caustic-photons", ("-1", "1.5", "many")), ("--caustic-radius", ("0", "-0.1", "nan"))):
        for v in values:
            r = run(cli, "render", "x.json", flag, v, "-o", "a.png")
            check("bad %s %s" % (flag, v), r.returncode == 2 and flag in r.stderr, r.stderr)
        check("help names " + flag, flag in run(cli, "--help").stdout)
    # Diagnostics of the preparation: a bad value exits 2 naming the flag.
    for flag, values in (("--keep-better-fit-tolerance", ("-1", "nan", "inf", "low")),
                         ("--prepare-seed", ("-1", "x")),
                         ("--window-reveal", ("-0.1", "nan", "inf", "11", "deep")),
                         ("--fit-unseen-ceiling", ("0.5,0.5", "0.5,0.5,0.5,0.5", "0.5,-1,0.5", "nan,0.5,0.5", "white")),
                         ("--unseen-ceiling", ("white", "", "FIT")),
                         ("--response-quick-margin", ("-1", "nan", "wide")),
                         ("--response-quick-copy", ("abc", "19200,0,5", "19200,1500,0", "-1,1500,5",
                                                    "19200,1500,5,2", "19200,1500,5,0", "19200,1500,5,1e-3,9",
                                                    "19200,1500,5,1e-3,-1", "19200,1500,5,1e-3,1,7"))):
        for v in values:
            r = run(cli, "render", "x.json", flag, v, "-o", "a.png")
            check("bad %s %s" % (flag, v), r.returncode == 2 and flag in r.stderr, r.stderr)
    r = run(cli, "render", os.path.join(tmp, "missing.json"), "-o", os.path.join(tmp, "o.png"))
    check("missing scene", r.returncode == 2 and "missing.json" in r.stderr, r.stderr)

    # `response`: the camera response of a photo or scene, and camera.response refused by key.
    out = os.path.join(tmp, "response.json")
    r = run(cli, "response", photo, "-o", out, "--quiet")
    ok = r.returncode == 0 and os.path.isfile(out)
    check("response of a photo", ok, r.stderr)
    if ok:
        j = json.load(open(out))
        t = j["table"]
        check("response table", len(t) == 256 and t[0] == 0 and t[255] == 1 and all(a < b for a, b in zip(t, t[1:])),
              str(t[:4]))
        check("response estimated", j["source"] == "estimated" and "estimate" in j, json.dumps(j)[:300])
    fixed = scene(lambda s: s.setdefault("camera", {}).update(response={"family": "toe_shoulder", "power": 0.7}),
                  "response_fixed")
    r = run(cli, "response", fixed, "-o", out, "--quiet")
    check("response from camera.response", r.returncode == 0 and json.load(open(out))["parameters"]["power"] == 0.7,
          r.stderr)
    for bad, key in (("gamma", "camera.response"), ({"family": "toe_shoulder", "toe": -1}, "camera.response.toe")):
        p = scene(lambda s: s.setdefault("camera", {}).update(response=bad), "response_bad")
        r = run(cli, "response", p, "-o", out)
        check("bad camera.response " + json.dumps(bad), r.returncode == 2 and key in r.stderr, r.stderr)
        r = run(cli, "render", p, "-o", os.path.join(tmp, "never.png"))
        check("render refuses bad camera.response", r.returncode == 2 and key in r.stderr, r.stderr)
    for bad in ("strong", 1.5, -0.1, [0.2]):  # camera.vignetting: "auto", "none" or v in [0, 0.9]
        p = scene(lambda s: s.setdefault("camera", {}).update(vignetting=bad), "vignetting_bad")
        r = run(cli, "render", p, "-o", os.path.join(tmp, "never.png"))
        check("render refuses camera.vignetting " + json.dumps(bad),
              r.returncode == 2 and "camera.vignetting" in r.stderr and "vignetting_bad.json" in r.stderr, r.stderr)
    r = run(cli, "response", photo)
    check("response needs -o", r.returncode == 2 and "-o" in r.stderr, r.stderr)
    r = run(cli, "response", photo, "-o", out, "--cue", "wavelet")
    check("response bad --cue", r.returncode == 2 and "--cue" in r.stderr, r.stderr)
    for q in ("0", "1.5", "nan", "x"):
        r = run(cli, "response", photo, "-o", out, "--noise-quantile", q)
        check("response bad --noise-quantile " + q, r.returncode == 2 and "--noise-quantile" in r.stderr, r.stderr)
    r = run(cli, "response", photo, "-o", out, "--quiet", "--cue", "noise", "--noise-quantile", "0.25")
    check("response --noise-quantile 0.25", r.returncode == 0 and json.load(open(out))["estimate"]["noise_quantile"] == 0.25,
          r.stderr)
    for w in ("-1", "nan", "x"):
        r = run(cli, "response", photo, "-o", out, "--cue", "noise-colour", "--edge-weight", w)
        check("response bad --edge-weight " + w, r.returncode == 2 and "--edge-weight" in r.stderr, r.stderr)
    r = run(cli, "response", photo, "-o", out, "--quiet", "--cue", "noise-colour", "--edge-weight", "10")
    est = json.load(open(out)).get("estimate", {}) if r.returncode == 0 else {}
    check("response --cue noise-colour --edge-weight 10", est.get("cue") == "noise-colour"
          and est.get("edge_weight") == 10 and "srgb_evidence" in est, r.stderr + json.dumps(est)[:300])
    for d in ("-0.1", "1.5", "nan", "x"):
        r = run(cli, "response", photo, "-o", out, "--max-dark-fill", d)
        check("response bad --max-dark-fill " + d, r.returncode == 2 and "--max-dark-fill" in r.stderr, r.stderr)
    r = run(cli, "response", photo, "-o", out, "--quiet", "--max-dark-fill", "0.12")
    est = json.load(open(out)).get("estimate", {}) if r.returncode == 0 else {}
    check("response --max-dark-fill 0.12", est.get("max_dark_fill") == 0.12 and 0 <= est.get("dark_fill", -1) <= 1
          and isinstance(est.get("dark_fill_evidence"), bool), r.stderr + json.dumps(est)[:300])

    # The README's first command: `demo` renders the bundled example wherever it is run from.
    demo = os.path.join(tmp, "example.png")
    r = subprocess.run([cli, "demo", "-o", demo, "--spp", "4", "--quiet"], capture_output=True, text=True,
                       timeout=300, cwd=tmp)
    check("demo renders", r.returncode == 0 and os.path.isfile(demo), r.stderr)
    if r.returncode == 0:
        import cv2
        import numpy as np
        got = cv2.imread(demo, cv2.IMREAD_COLOR).astype(float)
        ref = cv2.imread(photo, cv2.IMREAD_COLOR).astype(float)
        check("demo has the photo's size", got.shape == ref.shape, "%s against %s" % (got.shape, ref.shape))
        if got.shape == ref.shape:
            changed = np.abs(got - ref).max(axis=2) > 24
            check("demo inserts the object", 200 < changed.sum() < 0.5 * changed.size, "%d pixels changed" % changed.sum())
    r = run(cli, "demo", "scene.json", "-o", demo)
    check("demo takes no scene", r.returncode == 2 and "demo" in r.stderr, r.stderr)

    bad = os.path.join(tmp, "broken.json")
    open(bad, "w").write('{"format": "inlay-scene", "version": 1, "photo": ')
    r = run(cli, "render", bad, "-o", os.path.join(tmp, "o.png"))
    check("malformed json", r.returncode == 2 and "broken.json" in r.stderr, r.stderr)

    cases = [
        ("no photo key", lambda s: s.pop("photo"), "photo"),
        ("photo missing", lambda s: s.update(photo=os.path.join(tmp, "nope.png")), "photo"),
        ("height negative", lambda s: s["objects"][0].update(height_m=-1), "objects[0].height_m"),
        ("huge number", None, "camera.height_m"),
        ("wrong type", lambda s: s["objects"][0].update(base_px="here"), "objects[0].base_px"),
        ("zero-area light", lambda s: s["lights"][0].update(points=[[10, 10], [20, 20], [30, 30]]), "lights[0]"),
        ("base in the sky", lambda s: s["objects"][0].update(base_px=[200.0, 20.0]), "objects[0].base_px"),
        ("floor corner above horizon", lambda s: s["layout"]["back_wall_px"].__setitem__(3, [17.0, 100.0]), "layout.back_wall_px"),
        ("unknown preset", lambda s: s["objects"][0]["material"].update(preset="velvet"), "objects[0].material"),
        ("missing mesh file", lambda s: s["objects"][0].update(mesh="no_such_mesh.obj"), "objects[0].mesh"),
        ("two-point outline", lambda s: s.update(surfaces=[{"kind": "extrusion", "outline_px": [[200, 300], [260, 300]],
                                                            "height_click_px": [200, 350]}]), "surfaces[0].outline_px"),
        ("height click above horizon", lambda s: s.update(surfaces=[{"kind": "extrusion",
                                                                     "outline_px": [[200, 300], [260, 300], [260, 320], [200, 320]],
                                                                     "height_click_px": [200, 100]}]), "surfaces[0].height_click_px"),
        ("stairs profile on the floor", lambda s: s.update(surfaces=[{"kind": "stairs",
                                                                      "profile_px": [[200, 330], [260, 330], [260, 370]]}]),
         "surfaces[0].profile_px"),
        ("empty scribbles", lambda s: s.update(occluders=[{"foreground_scribbles_px": [],
                                                           "background_scribbles_px": [[[10, 10], [50, 10]]]}]),
         "occluders[0].foreground_scribbles_px"),
        ("grain not a boolean", lambda s: s.setdefault("render", {}).update(grain="yes"), "render.grain"),
        ("clamp negative", lambda s: s.setdefault("render", {}).update(clamp_indirect=-2), "render.clamp_indirect"),
        ("clamp a word", lambda s: s.setdefault("render", {}).update(clamp_indirect="bright"), "render.clamp_indirect"),
        ("clamp NaN", "NaN", "render.clamp_indirect"),
    ]
    out = os.path.join(tmp, "keep.png")
    for name, mutate, key in cases:
        if mutate is None:  # 1e999 overflows to infinity: written by hand
            p = os.path.join(tmp, "huge.json")
            txt = json.dumps(dict(base, photo=photo)).replace('"height_m": 1.6', '"height_m": 1e999')
            open(p, "w").write(txt)
        elif mutate == "NaN":  # Python's json writes NaN, which is not JSON: the reader must say where
            p = os.path.join(tmp, "nan_clamp.json")
            open(p, "w").write(json.dumps(dict(base, photo=photo, render={"clamp_indirect": float("nan")})))
        else:
            p = scene(mutate, name.replace(" ", "_"))
        open(out, "wb").write(b"users file")
        r = run(cli, "render", p, "-o", out, "--spp", "1", "--quiet")
        ok = r.returncode == 2 and key in r.stderr and len(r.stderr.strip().splitlines()) <= 2
        check(name, ok, "exit %d: %s" % (r.returncode, r.stderr.strip()))
        check(name + " leaves output", open(out, "rb").read() == b"users file")

    # A light outlined on the right wall with one point past the corner, left of the straight-ahead
    # line (its ray never meets the right wall's plane in front of the camera): the message names
    # the point and the corner to drag, not "the outline lies behind the camera".
    p = scene(lambda s: s["lights"][0].update(points=[[400, 100], [480, 100], [480, 200], [170, 150]]), "across_corner")
    r = run(cli, "render", p, "-o", out, "--spp", "1", "--quiet")
    check("outline across a corner", r.returncode == 2 and "lights[0].points" in r.stderr
          and "point 3 (170, 150) lies on the back wall" in r.stderr
          and "drag the back wall's bottom-right corner at (379, 262)" in r.stderr
          and "lies behind the camera" not in r.stderr, r.stderr.strip())

    # export: a bad extension is a usage error naming -o; a good one writes a .glb that starts
    # with glTF's magic; a bad subdivide level names its key.
    r = run(cli, "export", os.path.join(EXAMPLE, "scene.json"), "-o", os.path.join(tmp, "scene.txt"))
    check("export bad extension", r.returncode == 2 and "-o" in r.stderr, r.stderr)
    glb = os.path.join(tmp, "scene.glb")
    r = run(cli, "export", scene(lambda s: s["objects"][0].update(subdivide=2), "subdivided"), "-o", glb, "--quiet")
    check("export glb", r.returncode == 0 and open(glb, "rb").read(4) == b"glTF", r.stderr)
    r = run(cli, "export", scene(lambda s: s["objects"][0].update(subdivide=7), "oversubdivided"), "-o", glb)
    check("export bad subdivide", r.returncode == 2 and "objects[0].subdivide" in r.stderr, r.stderr)

    corrupt = os.path.join(tmp, "corrupt.png")
    open(corrupt, "wb").write(open(photo, "rb").read()[:2000])
    p = scene(lambda s: s.update(photo=corrupt), "corrupt")
    r = run(cli, "render", p, "-o", out, "--spp", "1")
    check("truncated photo", r.returncode == 2 and "corrupt.png" in r.stderr, r.stderr)

    # A real, small render: output, progress CSV, layers.
    p = scene(lambda s: None, "good")
    png, csvp, exr = (os.path.join(tmp, n) for n in ("good.png", "progress.csv", "layers.exr"))
    r = run(cli, "render", p, "-o", png, "--spp", "4", "--progress-csv", csvp, "--layers", exr)
    check("render ok", r.returncode == 0 and os.path.getsize(png) > 1000, r.stderr)
    rows = open(csvp).read().strip().splitlines() if os.path.exists(csvp) else []
    check("progress csv", len(rows) >= 2 and rows[0] == "seconds,spp,estimated_error" and rows[-1].split(",")[1] == "4", str(rows))
    check("layers", os.path.exists(exr) and os.path.getsize(exr) > 1000)
    check("no temp files left", not [f for f in os.listdir(tmp) if f.startswith(".") or ".tmp" in f], str(os.listdir(tmp)))
    check_replace_radiance(cli, p, png, tmp)

    # Ctrl-C stops within a second or two and writes nothing. It is sent once the render is
    # under way (its first progress line): a fixed sleep raced the program's start under load,
    # when the signal could arrive before main() installed its handler.
    stop = os.path.join(tmp, "stopped.png")
    proc = subprocess.Popen([cli, "render", p, "-o", stop, "--spp", "100000"], stderr=subprocess.PIPE, text=True)
    started = threading.Event()

    def watch():
        for line in proc.stderr:
            if line.startswith("inlay-cli: render "):
                started.set()
    reader = threading.Thread(target=watch, daemon=True)
    reader.start()
    check("render started", started.wait(timeout=300), "no progress line within 300 s")
    t0 = time.time()
    proc.send_signal(signal.SIGINT)
    try:
        proc.wait(timeout=10)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()
    dt = time.time() - t0
    check("ctrl-c", proc.returncode == 1 and dt < 2.5 and not os.path.exists(stop), "exit %s after %.2f s" % (proc.returncode, dt))
    print("ctrl-c stopped after %.2f s" % dt)

    shutil.rmtree(tmp, ignore_errors=True)
    return summary()


if __name__ == "__main__":
    sys.exit(main())
