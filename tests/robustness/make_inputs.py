#!/usr/bin/env python3
"""Writes tests/robustness/inputs/: one bad file per class of bad input and format, each with
a `<file>.error` beside it holding the text its error message must contain (BadInputTest.cpp
loads every file of the folder and checks it). Inputs the fuzzers found are added by hand as
`fuzz-<target>-<what>.<ext>` with their `.error`. Run from anywhere; it rewrites generated
files only (names not starting with "fuzz-")."""
import json, pathlib, struct, zlib, gzip, base64

here = pathlib.Path(__file__).resolve().parent / "inputs"
here.mkdir(exist_ok=True)
for p in here.iterdir():
    if not p.name.startswith("fuzz-"):
        p.unlink()


def case(name, data, error):
    (here / name).write_bytes(data if isinstance(data, bytes) else data.encode("latin-1"))
    (here / (name + ".error")).write_text(error + "\n")


H = "#Inventor V2.1 ascii\n"
# --- scene ---
case("scene-empty.iv", "", "empty file")
case("scene-bad-magic.iv", "Separator { Cube {} }\n", "missing header")
case("scene-binary-header.iv", "#Inventor V2.1 binary\n\x00\x01",
     "byte 22: unexpected end of file: a node type name needs 4 bytes, 2 left")
case("scene-truncated.iv", H + "Separator { Cube { width 2", "unexpected end of file")
case("scene-truncated-list.iv", H + "Coordinate3 { point [ 0 0 0, 1 1", "expected a number, found end of file")
case("scene-nan.iv", H + "Cube { width nan }\n", "expects SFFloat")
case("scene-inf.iv", H + "Cube { width 1e999 }\n", "expects SFFloat")
case("scene-float-overflow.iv", H + "Cube { width 1e39 }\n", "expects SFFloat")
case("scene-int-overflow.iv", H + "Switch { whichChild 99999999999 }\n", "expects SFInt32")
case("scene-wrong-type.iv", H + 'Cube { width "wide" }\n', "expects SFFloat")
case("scene-unknown-field.iv", H + "Cube { colour 1 }\n", "unknown field 'colour' in Cube")
case("scene-unknown-node.iv", H + "Teapot { }\n", "unknown node type 'Teapot'")
case("scene-undefined-use.iv", H + "Separator { USE nothing }\n", "USE of undefined name 'nothing'")
case("scene-self-use.iv", H + "DEF a Separator { USE a }\n", "USE of undefined name 'a'")
case("scene-deep-nesting.iv", H + "Separator {\n" * 1001 + "}\n" * 1001, "nested deeper than 1000")
case("scene-too-many-declared-fields.iv",
     H + "Foo { fields [ " + ", ".join("SFFloat f%d" % i for i in range(1025)) + " ] }\n",
     "declares more than 1024 fields")
case("scene-control-bytes.iv", H + "Cube { width 2 }\x01\x02\n", "control character")
case("scene-nul.iv", H + "Cube\x00 {}\n", "control character")
case("scene-non-utf8-word.iv", H + "Cube { wid\xff\xfeth 2 }\n", "unknown field 'wid\\xFF\\xFEth' in Cube")
case("scene-unclosed-string.iv", H + 'VolumeData { fileName "abc\n', "unterminated string")
case("scene-stray-brace.iv", H + "}\n", "unexpected '}'")

# --- binary scene files (docs/SCENE-FORMAT.md section 1.9) ---
BH = b"#Inventor V2.1 binary  \n"  # 24 bytes: the first item is at byte 24


def u32(v):
    return struct.pack(">I", v & 0xFFFFFFFF)


def f32(v):
    return struct.pack(">f", v)


def bstr(s):
    b = s.encode("latin-1")
    return u32(len(b)) + b + b"\0" * ((4 - len(b) % 4) % 4)


def bnode(type_name, fields=b"", nfields=0, children=None, flags=None):
    """A node: its type name, flags (IS_GROUP when it has children), the field word, the
    fields, then the child count and children."""
    if flags is None:
        flags = 2 if children is not None else 0
    out = bstr(type_name) + u32(flags) + u32(nfields) + fields
    if children is not None:
        out += u32(len(children)) + b"".join(children)
    return out


cube = bnode("Cube", bstr("width") + f32(2.0) + u32(0), 1)
case("scene-binary-truncated.iv", BH + bnode("Separator", children=[cube])[:-6],
     "unexpected end of file")
case("scene-binary-huge-count.iv",
     BH + bnode("Coordinate3", bstr("point") + u32(0xFFFFFF) + f32(1) * 6 + u32(0), 1),
     "byte 60: field 'point' of Coordinate3 expects MFVec3f: the list: 16777215 values of at least 12 bytes each do not fit in the 28 bytes left")
case("scene-binary-count-past-limit.iv",
     BH + bnode("Coordinate3", bstr("point") + u32(0x7FFFFFFF) + u32(0), 1),
     "more than 16777216 values in one MFVec3f field")
case("scene-binary-negative-count.iv",
     BH + bnode("Coordinate3", bstr("point") + u32(0xFFFFFFFF) + u32(0), 1),
     "negative value count -1")
case("scene-binary-huge-children.iv", BH + bstr("Separator") + u32(2) + u32(0) + u32(0xFFFFFFF0),
     "Separator has more than 1048576 children")
case("scene-binary-children-past-end.iv", BH + bstr("Separator") + u32(2) + u32(0) + u32(1000),
     "the children: 1000 values of at least 12 bytes each do not fit")
case("scene-binary-huge-string.iv", BH + u32(0x7FFFFFFF) + b"Cube",
     "a string of 2147483647 bytes, more than the limit of 67108864")
case("scene-binary-string-past-end.iv", BH + u32(0x100) + b"Cube",
     "unexpected end of file: a node type name is a string of 256 bytes, 4 left")
deep = b""
for i in range(1001):
    deep = bnode("Separator", children=[deep] if deep else [])
case("scene-binary-deep-nesting.iv", BH + deep, "nodes nested deeper than 1000 levels")
case("scene-binary-unknown-type.iv", BH + bnode("Teapot"),
     "byte 24: unknown node type 'Teapot' without a description of its fields")
case("scene-binary-unknown-field.iv", BH + bnode("Cube", bstr("colour") + f32(1) + u32(0), 1),
     "unknown field 'colour' in Cube")
case("scene-binary-nan.iv", BH + bnode("Cube", bstr("width") + u32(0x7FC00000) + u32(0), 1),
     "field 'width' of Cube expects SFFloat: a float is not a finite number")
case("scene-binary-bad-node-flags.iv", BH + bstr("Cube") + u32(0x80) + u32(0),
     "unknown node flags 0x80 for Cube")
case("scene-binary-bad-field-flags.iv", BH + bnode("Cube", bstr("width") + f32(1) + u32(0x10), 1),
     "unknown field flags 0x10 of 'width' of Cube")
case("scene-binary-undefined-use.iv", BH + bnode("Separator", children=[bstr("USE") + bstr("x")]),
     "USE of undefined name 'x'")
case("scene-binary-engine-as-child.iv",
     BH + bnode("Separator", children=[bnode("ElapsedTime", flags=1)]),
     "'ElapsedTime' is an engine: it can only be the source of a field connection")
case("scene-binary-v1.iv", b"#Inventor V1.0 binary  \n" + bnode("Cube"),
     "Inventor V1.0 binary files are not supported")

# --- NRRD (.nrrd attached, .nhdr detached) ---
N = "NRRD0004\ntype: uchar\ndimension: 3\n"
case("nrrd-bad-magic.nrrd", "NRRX0004\n" + "sizes: 2 2 2\n\n" + "\0" * 8, "NRRD")
case("nrrd-empty.nrrd", "", "NRRD")
case("nrrd-truncated-header.nrrd", N + "sizes: 2 2", "expected 3 sizes, got 2")
case("nrrd-truncated-data.nrrd", N + "sizes: 4 4 4\nencoding: raw\n\n" + "\1" * 10, "expected 64 bytes")
case("nrrd-huge-sizes.nrrd", N + "sizes: 100000 100000 100000\nencoding: raw\n\n", "exceed the limit of 65536")
case("nrrd-overflow-sizes.nrrd", N + "sizes: 65536 65536 65536\nencoding: raw\n\n", "exceeds the allocation limit")
case("nrrd-negative-size.nrrd", N + "sizes: 4 -4 4\nencoding: raw\n\n", "size -4 is out of range")
case("nrrd-nan-spacing.nrrd", N + "sizes: 2 2 2\nspacings: 1 nan 1\nencoding: raw\n\n" + "\0" * 8, "spacing must be")
case("nrrd-inf-spacing.nrrd", N + "sizes: 2 2 2\nspacings: 1 1 inf\nencoding: raw\n\n" + "\0" * 8, "spacing must be")
case("nrrd-dimension-4.nrrd", "NRRD0004\ntype: uchar\ndimension: 4\nsizes: 1 2 2 2\nencoding: raw\n\n", "dimension")
case("nrrd-unknown-type.nrrd", "NRRD0004\ntype: complex\ndimension: 3\nsizes: 2 2 2\nencoding: raw\n\n", "type")
case("nrrd-unknown-encoding.nrrd", N + "sizes: 2 2 2\nencoding: bzip2\n\n", "encoding")
case("nrrd-corrupt-gzip.nrrd", N + "sizes: 4 4 4\nencoding: gzip\n\n" + "\x1f\x8b\x08\x00garbagegarbage", "gzip")
case("nrrd-truncated-gzip.nrrd", (N + "sizes: 4 4 4\nencoding: gzip\n\n").encode()
     + gzip.compress(bytes(range(64)), mtime=0)[:40], "truncated gzip stream: it ends after")
case("nrrd-gzip-no-trailer.nrrd", (N + "sizes: 4 4 4\nencoding: gzip\n\n").encode()
     + gzip.compress(bytes(64), mtime=0)[:-8], "it ends before its end marker and checksum")
case("nrrd-gzip-bomb.nrrd", (N + "sizes: 4 4 4\nencoding: gzip\n\n").encode()
     + gzip.compress(bytes(10_000_000), mtime=0), "gzip")
case("nrrd-missing-data-file.nhdr", N + "sizes: 2 2 2\nencoding: raw\ndata file: nowhere.raw\n",
     "No such file or directory (the data file named in")
case("nrrd-data-file-is-folder.nhdr", N + "sizes: 2 2 2\nencoding: raw\ndata file: .\n",
     "not a regular file (the data file named in")

case("nrrd-non-utf8.nrrd", "NRRD0004\ntype: \xff\xfe\ndimension: 3\n", "type '\\xFF\\xFE'")
case("nrrd-nul.nrrd", "NRRD0004\ntype: uchar\x00\n", "NUL")

# --- MetaImage (.mha local data, .mhd separate file) ---
M = "ObjectType = Image\nNDims = 3\n"
case("metaimage-empty.mha", "", "ElementDataFile")
case("metaimage-bad-magic.mha", "\x89PNG\r\n\x1a\n\0\0\0\0", "")
case("metaimage-truncated.mha", M + "DimSize = 4 4 4\nElementType = MET_UCHAR\nElementDataFile = LOCAL\n"
     + "\0" * 7, "expected 64 bytes")
case("metaimage-huge.mha", M + "DimSize = 100000 100000 100000\nElementType = MET_UCHAR\n"
     "ElementDataFile = LOCAL\n", "exceed the limit of 65536")
case("metaimage-ndims-2.mha", "NDims = 2\nDimSize = 4 4\nElementType = MET_UCHAR\nElementDataFile = LOCAL\n", "NDims")
case("metaimage-nan-spacing.mha", M + "DimSize = 2 2 2\nElementSpacing = nan 1 1\nElementType = MET_UCHAR\n"
     "ElementDataFile = LOCAL\n" + "\0" * 8, "ElementSpacing")
case("metaimage-unknown-type.mha", M + "DimSize = 2 2 2\nElementType = MET_LONG_LONG\nElementDataFile = LOCAL\n", "ElementType")
case("metaimage-wrong-type.mha", M + "DimSize = two 2 2\nElementType = MET_UCHAR\nElementDataFile = LOCAL\n", "DimSize")
case("metaimage-corrupt-zlib.mha", M + "DimSize = 4 4 4\nElementType = MET_UCHAR\nCompressedData = True\n"
     "ElementDataFile = LOCAL\n" + "\x78\x9cnot zlib at all", "zlib")
case("metaimage-missing-file.mhd", M + "DimSize = 2 2 2\nElementType = MET_UCHAR\nElementDataFile = gone.raw\n",
     "No such file or directory (the data file named in")
case("metaimage-list.mhd", M + "DimSize = 2 2 2\nElementType = MET_UCHAR\nElementDataFile = LIST\n", "LIST")

# --- glTF (.gltf JSON, .glb binary) ---
def gltf(extra):
    g = {"asset": {"version": "2.0"}}
    g.update(extra)
    return json.dumps(g)

tri = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
uri = "data:application/octet-stream;base64," + base64.b64encode(tri).decode()
mesh = {"buffers": [{"byteLength": 36, "uri": uri}],
        "bufferViews": [{"buffer": 0, "byteLength": 36}],
        "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}]}
case("gltf-empty.gltf", "", "tinygltf")
case("gltf-bad-json.gltf", '{"asset": {"version": "2.0"', "tinygltf")
case("gltf-not-json.gltf", "\x00\x01\x02garbage", "tinygltf")
case("gltf-non-utf8.gltf", '{"asset": {"version": "2.0\xff\xfe"}}', "tinygltf")
case("gltf-wrong-type.gltf", gltf({"buffers": [{"byteLength": "big", "uri": uri}]}), "tinygltf")
case("gltf-truncated.glb", b"glTF\x02\x00\x00\x00\xff\x00\x00\x00\x10\x00", "tinygltf")
case("gltf-huge-count.gltf", gltf(dict(mesh, accessors=[{"bufferView": 0, "componentType": 5126,
     "count": 4294967295, "type": "VEC3"}])), "count 4294967295")
case("gltf-cycle.gltf", gltf(dict(mesh, nodes=[{"mesh": 0, "children": [1]}, {"children": [0]}],
     scenes=[{"nodes": [0]}])), "reached twice")
case("gltf-deep.gltf", gltf(dict(mesh, nodes=[{"children": [i + 1]} for i in range(300)] + [{"mesh": 0}],
     scenes=[{"nodes": [0]}])), "deeper than 256")
case("gltf-escaping-uri.gltf", gltf({"buffers": [{"byteLength": 4, "uri": "../../../../../../etc/hostname"}]}),
     "outside the folder of the glTF file")
case("gltf-absolute-uri.gltf", gltf({"buffers": [{"byteLength": 4, "uri": "/etc/hostname"}]}), "tinygltf")
case("gltf-missing-buffer.gltf", gltf({"buffers": [{"byteLength": 4, "uri": "missing.bin"}]}), "missing.bin")
ihdr = b"IHDR" + struct.pack(">IIBBBBB", 100000, 100000, 8, 6, 0, 0, 0)
big_png = b"\x89PNG\r\n\x1a\n" + struct.pack(">I", 13) + ihdr + struct.pack(">I", zlib.crc32(ihdr))
case("gltf-huge-image.gltf", gltf({"images": [{"uri": "data:image/png;base64," + base64.b64encode(big_png).decode()}]}),
     "exceeds the image limit")
case("gltf-bad-index.gltf", gltf(dict(mesh, meshes=[{"primitives": [{"attributes": {"POSITION": 7}}]}])), "does not exist")

# --- images (PNG, PFM) ---
case("image-bad-magic.png", "not a png at all", "PNG")
case("image-truncated.png", b"\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR\0\0", "PNG")
case("image-huge.png", big_png + struct.pack(">I", 0) + b"IEND" + struct.pack(">I", zlib.crc32(b"IEND")), "")
case("image-huge.pfm", "PF\n100000 100000\n-1\n", "")
case("image-truncated.pfm", "PF\n4 4\n-1\n\0\0\0\0", "PFM")
