#!/usr/bin/env python3
"""Writes the seed corpora of the df3 and mesh fuzz targets (docs/fuzzing.md) from scratch.

Usage: tools/make-fuzz-seeds.py [ROOT]  (default: the repository holding this script)

Each seed is a small valid file. Mesh seeds start with one byte that picks the extension the fuzz target
gives the file (fuzz/file_fuzzers.cpp kMeshFuzzExtensions: .obj .ply .stl .3ds .gltf .glb .fbx); df3 seeds
are df3 files as they are. Formats follow their public descriptions: df3 (POV-Ray 3.7 reference,
"Density_File"), Wavefront OBJ, Greg Turk's PLY, STL (3D Systems), Autodesk 3DS chunks, glTF 2.0
(Khronos), binary FBX 7.4 (Blender's developer notes on the FBX binary layout).
"""
import base64
import json
import pathlib
import struct
import sys
import zlib

EXTENSIONS = [".obj", ".ply", ".stl", ".3ds", ".gltf", ".glb", ".fbx"]

# A tetrahedron: 4 vertices, 4 outward triangles.
VERTS = [(0.0, 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)]
FACES = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def mesh_seed(extension, body):
    if isinstance(body, str):
        body = body.encode()
    return bytes([EXTENSIONS.index(extension)]) + body


def obj_files():
    plain = "".join(f"v {x} {y} {z}\n" for x, y, z in VERTS)
    plain += "".join(f"f {a + 1} {b + 1} {c + 1}\n" for a, b, c in FACES)
    quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvn 0 0 1\n"
    quad += "g square\nf 1/1/1 2/2/1 3/3/1 4/4/1\n"
    return {"tetrahedron.obj": plain, "quad-uv-normal.obj": quad}


def ply_files():
    ascii_ply = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
    ascii_ply += "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n"
    ascii_ply += "".join(f"{x} {y} {z}\n" for x, y, z in VERTS)
    ascii_ply += "".join(f"3 {a} {b} {c}\n" for a, b, c in FACES)
    # Binary little-endian with normals and uvs: the layout snell reads without Assimp (io/ply_binary.hpp).
    header = ("ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
              "property float z\nproperty float nx\nproperty float ny\nproperty float nz\n"
              "property float u\nproperty float v\nelement face 4\n"
              "property list uchar int vertex_indices\nend_header\n").encode()
    body = b"".join(struct.pack("<8f", x, y, z, 0, 0, 1, x, y) for x, y, z in VERTS)
    body += b"".join(struct.pack("<B3i", 3, *f) for f in FACES)
    big = ("ply\nformat binary_big_endian 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
           "property double z\nelement face 4\nproperty list uchar uint vertex_indices\nend_header\n").encode()
    big += b"".join(struct.pack(">3d", *v) for v in VERTS)
    big += b"".join(struct.pack(">B3I", 3, *f) for f in FACES)
    return {"ascii.ply": ascii_ply, "binary-normals-uv.ply": header + body, "big-endian.ply": big}


def stl_files():
    text = "solid tetra\n"
    binary = b"snell fuzz seed".ljust(80, b" ") + struct.pack("<I", len(FACES))
    for face in FACES:
        text += " facet normal 0 0 0\n  outer loop\n"
        text += "".join("   vertex {} {} {}\n".format(*VERTS[i]) for i in face)
        text += "  endloop\n endfacet\n"
        binary += struct.pack("<3f", 0, 0, 0)
        binary += b"".join(struct.pack("<3f", *VERTS[i]) for i in face) + b"\0\0"
    return {"ascii.stl": text + "endsolid tetra\n", "binary.stl": binary}


def chunk_3ds(chunk_id, payload):
    return struct.pack("<HI", chunk_id, 6 + len(payload)) + payload


def three_ds_files():
    points = chunk_3ds(0x4110, struct.pack("<H", len(VERTS)) + b"".join(struct.pack("<3f", *v) for v in VERTS))
    faces = chunk_3ds(0x4120, struct.pack("<H", len(FACES)) + b"".join(struct.pack("<4H", *f, 0) for f in FACES))
    mesh = chunk_3ds(0x4100, points + faces)
    obj = chunk_3ds(0x4000, b"tetra\0" + mesh)
    editor = chunk_3ds(0x3D3D, chunk_3ds(0x3D3E, struct.pack("<I", 3)) + obj)
    return {"tetrahedron.3ds": chunk_3ds(0x4D4D, chunk_3ds(0x0002, struct.pack("<I", 3)) + editor)}


def gltf_document(buffer_uri=None):
    positions = b"".join(struct.pack("<3f", *v) for v in VERTS)
    indices = b"".join(struct.pack("<3H", *f) for f in FACES)
    data = positions + indices
    buffer = {"byteLength": len(data)}
    if buffer_uri is not None:
        buffer["uri"] = buffer_uri + base64.b64encode(data).decode()
    doc = {
        "asset": {"version": "2.0"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 0}]}],
        "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.2, 0.1, 1.0]}}],
        "buffers": [buffer],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": len(positions)},
                        {"buffer": 0, "byteOffset": len(positions), "byteLength": len(indices)}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                       "min": [0, 0, 0], "max": [1, 1, 1]},
                      {"bufferView": 1, "componentType": 5123, "count": 12, "type": "SCALAR"}],
    }
    return doc, data


def gltf_files():
    doc, _ = gltf_document("data:application/octet-stream;base64,")
    embedded = json.dumps(doc, separators=(",", ":"))
    doc, data = gltf_document()
    text = json.dumps(doc, separators=(",", ":")).encode()
    text += b" " * (-len(text) % 4)
    data += b"\0" * (-len(data) % 4)
    glb_body = struct.pack("<I4s", len(text), b"JSON") + text + struct.pack("<I4s", len(data), b"BIN\0") + data
    glb = struct.pack("<4sII", b"glTF", 2, 12 + len(glb_body)) + glb_body
    return {"embedded.gltf": embedded, "tetrahedron.glb": glb}


class FbxId(int):
    """An object id: a 64-bit 'L' property, where plain numbers are 32-bit 'I'."""


def fbx_property(value):
    if isinstance(value, str):
        return b"S" + struct.pack("<I", len(value)) + value.encode()
    if isinstance(value, bytes):  # raw; used for the Model's name+class
        return b"S" + struct.pack("<I", len(value)) + value
    if isinstance(value, FbxId):
        return b"L" + struct.pack("<q", value)
    if isinstance(value, int):
        return b"I" + struct.pack("<i", value)
    if isinstance(value, list) and value and isinstance(value[0], float):
        return b"d" + struct.pack("<III", len(value), 0, 8 * len(value)) + struct.pack(f"<{len(value)}d", *value)
    if isinstance(value, list):
        return b"i" + struct.pack("<III", len(value), 0, 4 * len(value)) + struct.pack(f"<{len(value)}i", *value)
    if isinstance(value, float):
        return b"D" + struct.pack("<d", value)
    raise TypeError(value)


def fbx_node(name, properties=(), children=(), start=0):
    """A binary FBX 7.4 node record (32-bit offsets) at file offset `start`; a null record ends children."""
    props = b"".join(fbx_property(p) for p in properties)
    head_size = 13 + len(name)
    offset = start + head_size + len(props)
    nested = b""
    for child in children:
        record = child(offset)
        nested += record
        offset += len(record)
    if children:
        nested += b"\0" * 13
        offset += 13
    return struct.pack("<IIIB", offset, len(properties), len(props), len(name)) + name.encode() + props + nested


def node(name, properties=(), children=()):
    return lambda start: fbx_node(name, properties, children, start)


def fbx_files():
    polygon_indices = []
    for a, b, c in FACES:
        polygon_indices += [a, b, -c - 1]  # the last index of a polygon is stored as -(i+1)
    vertices = [float(x) for v in VERTS for x in v]
    top = [
        node("FBXHeaderExtension", children=[node("FBXHeaderVersion", [1003]), node("FBXVersion", [7400])]),
        node("GlobalSettings", children=[node("Version", [1000])]),
        node("Objects", children=[
            node("Geometry", [FbxId(100), b"tetra\0\x01Geometry", "Mesh"],
                 [node("Vertices", [vertices]), node("PolygonVertexIndex", [polygon_indices])]),
            node("Model", [FbxId(200), b"tetra\0\x01Model", "Mesh"], [node("Version", [232])]),
        ]),
        node("Connections", children=[node("C", ["OO", FbxId(100), FbxId(200)]), node("C", ["OO", FbxId(200), FbxId(0)])]),
    ]
    out = b"Kaydara FBX Binary  \0\x1a\0" + struct.pack("<I", 7400)
    for record in top:
        out += record(len(out))
    out += b"\0" * 13
    return {"tetrahedron.fbx": out}


def df3_files():
    def df3(nx, ny, nz, width, values):
        fmt = {1: "B", 2: "H", 4: "I"}[width]
        return struct.pack(">3H", nx, ny, nz) + struct.pack(f">{len(values)}{fmt}", *values)
    return {
        "bytes-2x2x2.df3": df3(2, 2, 2, 1, [0, 255, 128, 64, 32, 16, 8, 4]),
        "shorts-3x2x1.df3": df3(3, 2, 1, 2, [0, 65535, 1000, 20000, 30000, 40000]),
        "ints-1x1x2.df3": df3(1, 1, 2, 4, [0, 4294967295]),
        "sphere-8.df3": df3(8, 8, 8, 1, [max(0, 255 - 40 * int(((x - 3.5) ** 2 + (y - 3.5) ** 2 + (z - 3.5) ** 2) ** 0.5))
                                         for z in range(8) for y in range(8) for x in range(8)]),
    }


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent)
    corpus = root / "fuzz" / "corpus"
    mesh = {}
    for files in (obj_files(), ply_files(), stl_files(), three_ds_files(), gltf_files(), fbx_files()):
        for name, body in files.items():
            mesh[name] = mesh_seed(pathlib.Path(name).suffix, body)
    for folder, files in (("mesh", mesh), ("df3", df3_files())):
        (corpus / folder).mkdir(parents=True, exist_ok=True)
        for name, body in files.items():
            (corpus / folder / name).write_bytes(body if isinstance(body, bytes) else body.encode())
    print(f"wrote {len(mesh)} mesh and {len(df3_files())} df3 seeds under {corpus}")


if __name__ == "__main__":
    main()
