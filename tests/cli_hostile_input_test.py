#!/usr/bin/python3
"""The hostile-input table of issue #9, run through inlay-cli: every bad photo, mesh and scene
file below is generated here (no binary blobs), rendered with `inlay-cli render`, and checked for
exit status 2, a one-line message naming the file, the key and the reason, no crash, no hang (a
timeout per case) and the user's output file left untouched with no temporary file beside it.
Photos that are unusual but valid (16-bit, CMYK, EXIF orientation 6 and 8) must render, and
must look like the same photo stored plainly (orientation applied the right way round).
Needs nothing from ../shared.

usage: cli_hostile_input_test.py INLAY_CLI
"""
import json, os, re, shutil, struct, subprocess, sys, tempfile, zlib

import cv2
import numpy as np
import OpenImageIO as oiio

HERE = os.path.dirname(os.path.abspath(__file__))
EXAMPLE = os.path.join(HERE, "..", "resources", "example")
CASE_TIMEOUT = 120  # seconds; a hang fails the case instead of the whole suite
USERS_FILE = b"the user's own file"

from checks import check, summary  # noqa: E402


# ---------------------------------------------------------------- files the cases are made of

def png_chunk(kind, data):
    return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))


def png_with_header(width, height, idat):
    ihdr = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)  # 8-bit RGB
    return (b"\x89PNG\r\n\x1a\n" + png_chunk(b"IHDR", ihdr) + png_chunk(b"IDAT", idat) +
            png_chunk(b"IEND", b""))


def png_with_bad_idat_crc(png):
    """The first IDAT chunk's CRC flipped (the data itself intact)."""
    at = png.index(b"IDAT") - 4
    length = struct.unpack(">I", png[at:at + 4])[0]
    crc_at = at + 8 + length
    return png[:crc_at] + bytes(b ^ 0xFF for b in png[crc_at:crc_at + 4]) + png[crc_at + 4:]


def write_oiio(path, pixels, fmt, attrs=()):
    """pixels: H x W x C array; attrs: (name, value) pairs for the file's header."""
    h, w, c = pixels.shape
    spec = oiio.ImageSpec(w, h, c, fmt)
    for name, value in attrs:
        spec.attribute(name, value)
    out = oiio.ImageOutput.create(path)
    assert out and out.open(path, spec), oiio.geterror()
    assert out.write_image(pixels), out.geterror()
    out.close()


def stored_for_orientation(rgb, orientation):
    """The pixels a camera stores so that applying EXIF `orientation` shows `rgb`."""
    if orientation == 6:  # shown = stored turned 90 degrees clockwise
        return np.ascontiguousarray(np.rot90(rgb, 1))
    if orientation == 8:  # shown = stored turned 90 degrees counter-clockwise
        return np.ascontiguousarray(np.rot90(rgb, -1))
    raise ValueError(orientation)


OBJ_TRIANGLE = "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
GLTF_POSITIONS = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)


def gltf(byte_length_declared, view_offset, view_length, data=GLTF_POSITIONS):
    import base64
    uri = "data:application/octet-stream;base64," + base64.b64encode(data).decode()
    return json.dumps({
        "asset": {"version": "2.0"},
        "buffers": [{"uri": uri, "byteLength": byte_length_declared}],
        "bufferViews": [{"buffer": 0, "byteOffset": view_offset, "byteLength": view_length}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
        "nodes": [{"mesh": 0}], "scenes": [{"nodes": [0]}], "scene": 0})


# ---------------------------------------------------------------- the table

class Case:
    """`make(tmp, ctx)` writes the case's files and returns the scene file to render; `expect`
    lists regular expressions the message must match (file, key, reason), or None when the
    input is valid and must render."""

    def __init__(self, name, make, expect):
        self.name, self.make, self.expect = name, make, expect


def scene_case(name, mutate, expect):
    def make(tmp, ctx):
        return ctx.scene(mutate, name)
    return Case(name, make, expect)


def photo_case(name, write_photo, expect, file_name):
    def make(tmp, ctx):
        path = os.path.join(tmp, file_name)
        write_photo(path, ctx)
        return ctx.scene(lambda s: s.update(photo=path), name)
    return Case(name, make, expect)


def mesh_case(name, file_name, text, expect):
    def make(tmp, ctx):
        path = os.path.join(tmp, file_name)
        open(path, "w").write(text)
        return ctx.scene(lambda s: s["objects"][0].update(mesh=path, material={"preset": "diffuse"}), name)
    return Case(name, make, expect)


def raw_scene_case(name, file_name, text_of, expect):
    def make(tmp, ctx):
        path = os.path.join(tmp, file_name)
        with open(path, "w") as f:
            f.write(text_of(ctx))
        return path
    return Case(name, make, expect)


def truncated_jpeg(path, ctx):
    ok, buf = cv2.imencode(".jpg", ctx.bgr, [cv2.IMWRITE_JPEG_QUALITY, 95])
    open(path, "wb").write(buf.tobytes()[:len(buf) // 2])


def wrong_crc_png(path, ctx):
    ok, buf = cv2.imencode(".png", ctx.bgr)
    open(path, "wb").write(png_with_bad_idat_crc(buf.tobytes()))


def truncated_png(path, ctx):
    ok, buf = cv2.imencode(".png", ctx.bgr)
    open(path, "wb").write(buf.tobytes()[:len(buf) // 2])


def bad_deflate_png(path, ctx):
    # Every chunk's CRC is right, but the compressed pixels are garbage: libpng's own check.
    open(path, "wb").write(png_with_header(512, 384, b"\x78\x9c" + bytes(range(7, 250))))


def huge_chunk_png(path, ctx):
    # Found by fuzz_image: a chunk header claiming 1.2 GB in a 40-byte file (was allocated).
    open(path, "wb").write(b"\x89PNG\r\n\x1a\n" + struct.pack(">I", 0x492A0008) + b"IHDR" + b"\0" * 24)


def huge_attribute_exr(path, ctx):
    # Found by fuzz_image: an EXR header attribute claiming 1.6 GB in a tiny file (OpenEXR
    # allocated and cleared it before reading).
    open(path, "wb").write(b"\x76\x2f\x31\x01" + struct.pack("<i", 2) + b"channels\0chlist\0" +
                           struct.pack("<i", 0x61626364) + b"\0" * 40)


def one_pixel(path, ctx):
    cv2.imwrite(path, np.full((1, 1, 3), 128, np.uint8))


def bomb_header(path, ctx):
    # 60000 x 60000 RGB claimed, a few bytes of data: decoding it would need 43 GB.
    open(path, "wb").write(png_with_header(60000, 60000, zlib.compress(b"\0" * 1000)))


def sixteen_bit(path, ctx):
    cv2.imwrite(path, ctx.bgr.astype(np.uint16) * 257)


def cmyk_tiff(path, ctx):
    # OpenImageIO's TIFF writer stores RGB as CMYK (PHOTOMETRIC_SEPARATED) when asked to.
    write_oiio(path, ctx.rgb, "uint8", [("tiff:ColorSpace", "CMYK")])


def oriented_jpeg(orientation):
    def write(path, ctx):
        write_oiio(path, stored_for_orientation(ctx.rgb, orientation), "uint8",
                   [("Orientation", orientation), ("CompressionQuality", 98)])
    return write


def huge_object_list(ctx):
    s = ctx.base_with_photo()
    s["objects"] = []
    text = json.dumps(s)
    one = '{"mesh": "builtin:sphere", "base_px": [200, 300]}'
    return text.replace('"objects": []', '"objects": [' + ",".join([one] * 1_000_000) + "]")


def deep_nesting(ctx):
    return json.dumps(ctx.base_with_photo())[:-1] + ', "extra": ' + "[" * 100_000 + "]" * 100_000 + "}"


def oversized_scene(ctx):
    return json.dumps(ctx.base_with_photo())[:-1] + ', "padding": "' + "x" * (65 << 20) + '"}'


def nan_literal(ctx):
    return json.dumps(ctx.base_with_photo()).replace('"height_m": 1.6', '"height_m": NaN')


CASES = [
    # Photos.
    photo_case("truncated jpeg", truncated_jpeg, [r"truncated\.jpg", r"photo", r"corrupt|truncated|premature"], "truncated.jpg"),
    photo_case("png wrong crc", wrong_crc_png, [r"badcrc\.png", r"photo", r"corrupt PNG: chunk 'IDAT' at byte \d+ fails its CRC check"], "badcrc.png"),
    photo_case("truncated png", truncated_png, [r"cut\.png", r"photo", r"truncated PNG: the file ends inside chunk 'IDAT'"], "cut.png"),
    photo_case("png with garbage pixels", bad_deflate_png, [r"garbage\.png", r"photo", r"corrupt PNG: the compressed pixel data is invalid"], "garbage.png"),
    photo_case("png chunk claiming 1.2 GB", huge_chunk_png, [r"liar\.png", r"photo", r"truncated PNG: the file ends inside chunk 'IHDR' at byte 8"], "liar.png"),
    photo_case("exr attribute claiming 1.6 GB", huge_attribute_exr, [r"liar\.exr", r"photo", r"corrupt EXR: attribute 'channels' at byte 8 claims 1633837924 bytes, the file has 40 left"], "liar.exr"),
    photo_case("1x1 image", one_pixel, [r"tiny\.png", r"photo", r"1 x 1 pixels is too small \(at least 32 per side\)"], "tiny.png"),
    photo_case("60000x60000 header", bomb_header, [r"bomb\.png", r"photo", r"60000 x 60000.*exceeds the limit"], "bomb.png"),
    photo_case("16-bit png", sixteen_bit, None, "deep.png"),
    photo_case("cmyk tiff", cmyk_tiff, None, "cmyk.tif"),
    photo_case("exif orientation 6", oriented_jpeg(6), None, "rot6.jpg"),
    photo_case("exif orientation 8", oriented_jpeg(8), None, "rot8.jpg"),
    # Meshes.
    mesh_case("obj nan vertex", "nan.obj", OBJ_TRIANGLE + "v nan 0 0\nf 1 2 4\n",
              [r"nan\.obj", r"objects\[0\]\.mesh", r"line 4", r"finite|NaN|nan"]),
    mesh_case("obj index out of range", "range.obj", OBJ_TRIANGLE + "f 1 2 7\n",
              [r"range\.obj", r"objects\[0\]\.mesh", r"line 4", r"out of range"]),
    mesh_case("obj negative index out of range", "negative.obj", OBJ_TRIANGLE + "f -1 -2 -9\n",
              [r"negative\.obj", r"objects\[0\]\.mesh", r"line 4", r"vertex index -9 refers before the first vertex"]),
    mesh_case("ply lies about vertex count", "lying.ply",
              "ply\nformat ascii 1.0\nelement vertex 100\nproperty float x\nproperty float y\n"
              "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
              "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
              [r"lying\.ply", r"objects\[0\]\.mesh\.header line 3",
               r"more data than the file holds: 'vertex' claims 100 entries, so the data after "
               r"end_header needs at least 600 bytes, but the file holds 26"]),
    mesh_case("binary ply lies about face count", "lying_bin.ply",
              "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
              "property float y\nproperty float z\nelement face 5000000\n"
              "property list uchar int vertex_indices\nend_header\n" + "\0" * 36,
              [r"lying_bin\.ply", r"objects\[0\]\.mesh\.header line 7",
               r"more data than the file holds: 'face' claims 5000000 entries, so the data after "
               r"end_header needs at least 5000036 bytes, but the file holds 36"]),
    mesh_case("gltf view past its buffer", "past.gltf", gltf(36, 24, 36),
              [r"past\.gltf", r"objects\[0\]\.mesh", r"bufferViews\[0\]", r"past|beyond|exceeds|outside"]),
    mesh_case("gltf buffer shorter than declared", "short.gltf", gltf(4096, 0, 36),
              [r"short\.gltf", r"objects\[0\]\.mesh", r"buffers\[0\]", r"byteLength|shorter|bytes"]),
    # Scene files.
    scene_case("wrong type", lambda s: s["objects"][0].update(height_m="tall"),
               [r"wrong_type\.json", r"objects\[0\]\.height_m", r"number"]),
    scene_case("wrong type of a section", lambda s: s.update(lights={"kind": "polygon_px"}),
               [r"wrong_type_of_a_section\.json", r"lights", r"array"]),
    raw_scene_case("nan literal", "nan.json", nan_literal, [r"nan\.json", r"line|byte|column", r"invalid|NaN|parse"]),
    scene_case("missing photo", lambda s: s.update(photo="no_such_photo.jpg"),
               [r"missing_photo\.json", r"photo", r"not found", r"no_such_photo\.jpg"]),
    raw_scene_case("a million objects", "million.json", huge_object_list,
                   [r"million\.json", r"objects", r"1000000 objects exceed the limit of 10000"]),
    raw_scene_case("nesting 100000 deep", "deep.json", deep_nesting,
                   [r"deep\.json", r"extra", r"nest"]),
    raw_scene_case("scene file over 64 MiB", "big.json", oversized_scene,
                   [r"big\.json", r"bytes exceeds the limit"]),
    # Paths leading out of the scene's folder: allowed (the harness writes absolute paths to
    # photos elsewhere), but what they name must be a regular file.
    scene_case("photo path to a folder outside", lambda s: s.update(photo="../"),
               [r"photo_path_to_a_folder_outside\.json", r"photo", r"not a regular file"]),
    scene_case("photo path to a device", lambda s: s.update(photo="/dev/zero"),
               [r"photo_path_to_a_device\.json", r"photo", r"/dev/zero", r"not a regular file"]),
    Case("mesh path to a folder outside", lambda tmp, ctx: ctx.scene(
        lambda s: s["objects"][0].update(mesh="../" + os.path.basename(ctx.tmp) + "/folder.obj"),
        "mesh path to a folder outside"),
         [r"mesh_path_to_a_folder_outside\.json", r"objects\[0\]\.mesh", r"folder\.obj", r"not a regular file"]),
    scene_case("mesh path to a missing file outside", lambda s: s["objects"][0].update(mesh="../../no/such/mesh.ply"),
               [r"missing_file_outside\.json", r"objects\[0\]\.mesh", r"file not found: /.*no/such/mesh\.ply"]),
]


class Context:
    def __init__(self, tmp):
        self.tmp = tmp
        self.base = json.load(open(os.path.join(EXAMPLE, "scene.json")))
        self.photo = os.path.abspath(os.path.join(EXAMPLE, "photo.png"))
        self.bgr = cv2.imread(self.photo, cv2.IMREAD_COLOR)
        self.rgb = np.ascontiguousarray(self.bgr[:, :, ::-1])
        os.mkdir(os.path.join(tmp, "folder.obj"))

    def base_with_photo(self):
        s = json.loads(json.dumps(self.base))
        s["photo"] = self.photo
        return s

    def scene(self, mutate, name):
        s = self.base_with_photo()
        mutate(s)
        p = os.path.join(self.tmp, re.sub(r"[^a-z0-9]+", "_", name.lower()) + ".json")
        with open(p, "w") as f:
            json.dump(s, f)
        return p


def render(cli, scene, out):
    try:
        r = subprocess.run([cli, "render", scene, "-o", out, "--spp", "1", "--quiet"],
                           capture_output=True, text=True, timeout=CASE_TIMEOUT)
        return r.returncode, r.stderr.strip()
    except subprocess.TimeoutExpired:
        return "timeout", ""


def leftovers(folder, keep):
    return [f for f in os.listdir(folder) if f not in keep and (f.startswith(".") or "tmp" in f)]


def run_case(cli, case, ctx, reference):
    folder = tempfile.mkdtemp(prefix="case_", dir=ctx.tmp)
    scene = case.make(folder, ctx)
    out = os.path.join(folder, "render.png")
    open(out, "wb").write(USERS_FILE)
    before = set(os.listdir(folder))
    status, err = render(cli, scene, out)
    print("%-36s exit %s: %s" % (case.name, status, err[:300]))
    check(case.name + ": no crash or hang", status in (0, 1, 2), "exit %s" % status)
    check(case.name + ": no temporary file left", not leftovers(folder, before), str(os.listdir(folder)))
    if case.expect is None:
        check(case.name + ": renders", status == 0, err)
        if status == 0:
            got = cv2.imread(out, cv2.IMREAD_COLOR)
            same_shape = got is not None and got.shape == reference.shape
            diff = np.abs(got.astype(float) - reference).mean() if same_shape else 1e9
            check(case.name + ": looks like the plain photo", diff < 3.0,
                  "shape %s, mean |diff| %.2f" % (None if got is None else got.shape, diff))
        return
    check(case.name + ": exit 2", status == 2, "exit %s: %s" % (status, err))
    check(case.name + ": one line", len(err.splitlines()) == 1, err)
    for pattern in case.expect:
        check(case.name + ": says " + pattern, re.search(pattern, err) is not None, err)
    check(case.name + ": output untouched", open(out, "rb").read() == USERS_FILE)


def main():
    cli = os.path.abspath(sys.argv[1])
    only = sys.argv[2] if len(sys.argv) > 2 else None
    tmp = tempfile.mkdtemp(prefix="inlay_hostile_")
    try:
        ctx = Context(tmp)
        ref_out = os.path.join(tmp, "reference.png")
        status, err = render(cli, ctx.scene(lambda s: None, "reference"), ref_out)
        check("reference render", status == 0, err)
        reference = cv2.imread(ref_out, cv2.IMREAD_COLOR).astype(float) if status == 0 else None
        for case in CASES:
            if only and only not in case.name:
                continue
            run_case(cli, case, ctx, reference)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    return summary()


if __name__ == "__main__":
    sys.exit(main())
