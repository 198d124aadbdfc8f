#!/usr/bin/python3
"""Writes the seed corpora of the fuzz targets (tests/fuzz/corpus/<target>/): small valid files
authored here, one per feature the parser handles. Run again after changing a seed; crashes
found by the fuzzers are added beside the seeds by hand (named crash-*), never regenerated.

usage: make_corpus.py [CORPUS_DIR]
"""
import base64, json, os, struct, sys

import numpy as np
import OpenImageIO as oiio

HERE = os.path.dirname(os.path.abspath(__file__))


def put(root, target, name, data):
    d = os.path.join(root, target)
    os.makedirs(d, exist_ok=True)
    mode = "wb" if isinstance(data, bytes) else "w"
    with open(os.path.join(d, name), mode) as f:
        f.write(data)


def scenes(root):
    example = json.load(open(os.path.join(HERE, "..", "..", "resources", "example", "scene.json")))
    example["photo"] = "photo.png"
    put(root, "scene_file", "example.json", json.dumps(example, indent=1))
    full = {
        "format": "inlay-scene", "version": 1, "photo": "photo.png",
        "camera": {"height_m": 1.5, "focal_px": 600, "principal_px": [256, 192],
                   "vanishing_points_px": [[3000, 150], [256, 1e7], [180, 150]]},
        "layout": {"back_wall_px": [[10, 50], [380, 60], [370, 260], [20, 270]]},
        "lights": [{"kind": "polygon_px", "points": [[100, 10], [200, 10], [200, 40], [100, 40]]},
                   {"kind": "rect_m", "corners": [[0, 2, -3], [1, 2, -3], [1, 2, -4], [0, 2, -4]],
                    "rgb": [2, 2, 2], "refine": False}],
        "shafts": [{"shaft_box_px": [10, 200, 80, 260], "direction": [0.2, -1, 0.1]}],
        "surfaces": [{"kind": "extrusion", "outline_px": [[200, 250], [260, 250], [260, 270], [200, 270]],
                      "height_click_px": [200, 300], "thickness_m": 0.05},
                     {"kind": "stairs", "base_px": [300, 320], "steps": 3, "rise_m": 0.17,
                      "run_m": 0.28, "width_m": 0.9, "climb_axis": "+x"}],
        "occluders": [{"foreground_scribbles_px": [[[50, 300], [60, 310]]],
                       "background_scribbles_px": [[[30, 300], [35, 330]]]}],
        "objects": [{"mesh": "mesh.obj", "base_px": [250, 320], "height_m": 0.4, "yaw_deg": 30,
                     "material": {"preset": "glass", "ior": 1.45}},
                    {"mesh": "builtin:cube", "base_px": [150, 330],
                     "material": {"preset": "emissive", "rgb": [3, 2, 1]}}],
        "render": {"spp": 16, "seconds": None, "exposure": 0.5, "seed": 7},
    }
    put(root, "scene_file", "every_section.json", json.dumps(full, indent=1))


def meshes(root):
    put(root, "mesh_obj", "triangle.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
    put(root, "mesh_obj", "quad_relative.obj",
        "# quad with texture coordinates and normals, relative indices\n"
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"
        "usemtl red\nf -4/-4/-1 -3/-3/-1 -2/-2/-1 -1/-1/-1\n")
    put(root, "mesh_obj", "groups.obj",
        "o a\ng one\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\ns 1\nf 1//1 2//1 3//1\nvn 0 0 1\n"
        "g two\nf 1 3 4\nf 2 3 4\n")
    ply_head = ("ply\nformat {fmt} 1.0\nelement vertex {nv}\nproperty float x\nproperty float y\n"
                "property float z\n{extra}element face {nf}\nproperty list uchar int vertex_indices\n"
                "end_header\n")
    put(root, "mesh_ply", "ascii.ply", ply_head.format(fmt="ascii", nv=4, nf=2, extra="")
        + "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n")
    extra = "property float nx\nproperty float ny\nproperty float nz\n"
    body = b"".join(struct.pack("<6f", x, y, 0, 0, 0, 1) for x, y in ((0, 0), (1, 0), (1, 1), (0, 1)))
    body += struct.pack("<B4i", 4, 0, 1, 2, 3)
    put(root, "mesh_ply", "binary_quad_normals.ply",
        ply_head.format(fmt="binary_little_endian", nv=4, nf=1, extra=extra).encode() + body)
    body = b"".join(struct.pack(">3f", *v) for v in ((0, 0, 0), (1, 0, 0), (0, 1, 0)))
    put(root, "mesh_ply", "big_endian.ply",
        ply_head.format(fmt="binary_big_endian", nv=3, nf=1, extra="").encode() + body +
        struct.pack(">B3i", 3, 0, 1, 2))
    positions = struct.pack("<12f", 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0)
    indices = struct.pack("<6H", 0, 1, 2, 0, 2, 3)
    buf = positions + indices
    doc = {
        "asset": {"version": "2.0"},
        "buffers": [{"byteLength": len(buf)}],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 0]},
                      {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}],
        "materials": [{"name": "m", "pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0.2, 1],
                                                            "metallicFactor": 0.3}}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
        "nodes": [{"mesh": 0, "scale": [2, 2, 2]}], "scenes": [{"nodes": [0]}], "scene": 0}
    embedded = json.loads(json.dumps(doc))
    embedded["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64.b64encode(buf).decode()
    put(root, "mesh_gltf", "embedded.gltf", json.dumps(embedded))
    chunk = json.dumps(doc).encode()
    chunk += b" " * (-len(chunk) % 4)
    binc = buf + b"\0" * (-len(buf) % 4)
    glb = (struct.pack("<4sII", b"glTF", 2, 12 + 8 + len(chunk) + 8 + len(binc)) +
           struct.pack("<I4s", len(chunk), b"JSON") + chunk + struct.pack("<I4s", len(binc), b"BIN\0") + binc)
    put(root, "mesh_gltf", "binary.glb", glb)


def images(root, tmp):
    rng = np.random.default_rng(1)

    def write(name, pixels, fmt, attrs=()):
        path = os.path.join(tmp, name)
        h, w, c = pixels.shape
        spec = oiio.ImageSpec(w, h, c, fmt)
        for k, v in attrs:
            spec.attribute(k, v)
        out = oiio.ImageOutput.create(path)
        assert out.open(path, spec), oiio.geterror()
        out.write_image(pixels)
        out.close()
        put(root, "image", name, open(path, "rb").read())

    rgb8 = rng.integers(0, 256, (8, 8, 3), dtype=np.uint8)
    write("rgb8.png", rgb8, "uint8")
    write("grey16.png", rng.integers(0, 65536, (6, 5, 1), dtype=np.uint16), "uint16")
    write("rgba8.png", rng.integers(0, 256, (4, 4, 4), dtype=np.uint8), "uint8")
    write("oriented6.jpg", rng.integers(0, 256, (16, 8, 3), dtype=np.uint8), "uint8", [("Orientation", 6)])
    write("small.tif", rgb8, "uint8")
    write("cmyk.tif", rgb8, "uint8", [("tiff:ColorSpace", "CMYK")])
    write("half.exr", rng.random((4, 4, 3), dtype=np.float32), "half")
    write("radiance.hdr", rng.random((4, 4, 3), dtype=np.float32), "float")


def main():
    import tempfile
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "corpus")
    scenes(root)
    meshes(root)
    with tempfile.TemporaryDirectory() as tmp:
        images(root, tmp)
    for d in sorted(os.listdir(root)):
        print(d, len(os.listdir(os.path.join(root, d))), "files")


if __name__ == "__main__":
    main()
