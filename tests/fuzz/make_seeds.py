#!/usr/bin/env python3
"""Writes the seed corpora of tests/fuzz/corpus/<format>/ and the dictionaries <format>.dict.

Seeds are small valid (and a few nearly valid) files of every variant each reader handles, so
the fuzzer starts deep inside the parsers. Scene seeds are the example scenes. The first byte
of a NRRD/MetaImage seed picks attached/detached, the first 6 bytes of a raw seed the layout
(see the Fuzz*.cpp targets). Run from anywhere; it rewrites the folders."""
import base64, gzip, json, pathlib, re, shutil, struct, zlib

here = pathlib.Path(__file__).resolve().parent
repo = here.parent.parent
corpus = here / "corpus"


def folder(name):
    d = corpus / name
    shutil.rmtree(d, ignore_errors=True)
    d.mkdir(parents=True)
    return d


def put(d, name, data):
    (d / name).write_bytes(data if isinstance(data, bytes) else data.encode())


# --- scene: every example scene (all a few KB) plus small hand-written edge cases ---
d = folder("scene")
for p in sorted(list(repo.glob("examples/**/*.iv")) + list(repo.glob("tests/**/*.iv"))):
    if p.stat().st_size <= 4096:
        put(d, p.parent.name + "-" + p.name, p.read_bytes())
put(d, "unknown-node.iv", "#Inventor V2.1 ascii\nFoo { fields [ SFFloat a, MFVec3f b, SFNode n ]"
    " a 1.5 b [ 1 2 3, 4 5 6 ] n Cube {} }\n")
put(d, "def-use.iv", "#Inventor V2.1 ascii\nSeparator { DEF m+0 Material { diffuseColor 1 0 0 }"
    " USE m+0 Switch { whichChild -3 Cube { width 2 } } }\n")
put(d, "strings.iv", '#Inventor V2.1 ascii\nVolumeData { fileName "a \\"b\\".raw" dimensions 2 2 2'
    ' dataType UBYTE }\n')

# --- raw: 6 layout bytes + file ---
d = folder("raw")
put(d, "ubyte-4x4x4", bytes([3, 3, 3, 0, 0, 0]) + bytes(range(64)))
put(d, "ushort-be-2x3x2", bytes([1, 2, 1, 0x81, 0, 1]) + bytes(range(24)))
put(d, "float-skip", bytes([1, 1, 1, 3, 4, 2]) + b"HEAD" + struct.pack("<8f", *range(8)))
put(d, "short-gzip", bytes([1, 1, 1, 2, 0, 0]) + gzip.compress(bytes(range(16)), mtime=0))

# --- nrrd: selector byte (0 attached .nrrd, 1 detached .nhdr) + file ---
d = folder("nrrd")
nrrd = "NRRD0004\n# comment\ntype: uchar\ndimension: 3\nsizes: 4 4 4\nspacings: 1 1 2\n"
put(d, "raw-uchar", b"\0" + (nrrd + "encoding: raw\n\n").encode() + bytes(range(64)))
put(d, "gzip-ushort-big", b"\0" + ("NRRD0005\ntype: unsigned short\ndimension: 3\nsizes: 3 3 3\n"
    "endian: big\nencoding: gzip\nspace directions: (1,0,0) (0,2,0) (0,0,0.5)\nkinds: domain "
    "domain domain\n\n").encode() + gzip.compress(bytes(range(54)), mtime=0))
put(d, "float-byteskip", b"\0" + ("NRRD0004\ntype: float\ndimension: 3\nsizes: 2 2 2\nencoding: "
    "raw\nbyte skip: -1\nendian: little\n\n").encode() + b"xx" + struct.pack("<8f", *range(8)))
put(d, "detached", b"\1" + ("NRRD0004\ntype: uint8\ndimension: 3\nsizes: 16 16 16\nencoding: raw"
    "\ndata file: data.raw\n").encode())
put(d, "detached-gz-lineskip", b"\1" + ("NRRD0004\ntype: uchar\ndimension: 3\nsizes: 4 4 4\n"
    "encoding: gz\ndatafile: data.raw.gz\nline skip: 0\n").encode())
put(d, "short-spacings", b"\0" + ("NRRD0004\ntype: short\ndimension: 3\nsizes: 2 2 1\nencoding: "
    "raw\nspacings: 0.5 0.5 3\nspace origin: (0,0,0)\n\n").encode() + struct.pack("<4h", -2, -1, 0, 1))

# --- metaimage: selector byte (0 .mha, 1 .mhd) + file ---
d = folder("metaimage")
mha = ("ObjectType = Image\nNDims = 3\nDimSize = 4 4 4\nElementType = MET_UCHAR\n"
       "ElementSpacing = 1 1 2\nBinaryData = True\n")
put(d, "local-uchar", b"\0" + (mha + "ElementDataFile = LOCAL\n").encode() + bytes(range(64)))
put(d, "short-msb", b"\0" + ("NDims = 3\nDimSize = 2 2 2\nElementType = MET_SHORT\n"
    "BinaryDataByteOrderMSB = True\nElementSize = 1 1 1\nElementDataFile = LOCAL\n").encode()
    + struct.pack(">8h", *range(-4, 4)))
put(d, "zlib-float", b"\0" + ("NDims = 3\nDimSize = 2 2 2\nElementType = MET_FLOAT\n"
    "CompressedData = True\nCompressedDataSize = %d\nElementDataFile = LOCAL\n" %
    len(zlib.compress(struct.pack("<8f", *range(8))))).encode()
    + zlib.compress(struct.pack("<8f", *range(8))))
put(d, "headersize-end", b"\0" + ("NDims = 3\nDimSize = 2 2 2\nElementType = MET_USHORT\n"
    "HeaderSize = -1\nElementDataFile = LOCAL\n").encode() + bytes(range(16)))
put(d, "detached", b"\1" + ("ObjectType = Image\nNDims = 3\nDimSize = 16 16 16\n"
    "ElementType = MET_UCHAR\nElementDataFile = data.raw\n").encode())

# --- gltf: .gltf JSON (embedded and external buffers, textures) and .glb ---
d = folder("gltf")
positions = struct.pack("<9f", 0, 0, 0, 1, 0, 0, 0, 1, 0)
indices = struct.pack("<3H", 0, 1, 2) + b"\0\0"
uvs = struct.pack("<6f", 0, 0, 1, 0, 0, 1)
blob = positions + indices + uvs


def png_1x1():
    def chunk(t, b):
        return struct.pack(">I", len(b)) + t + b + struct.pack(">I", zlib.crc32(t + b))
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 1, 1, 8, 6, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(b"\0\xff\x80\x40\xff")) + chunk(b"IEND", b""))


def gltf(uri, textured=False):
    g = {"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
         "nodes": [{"mesh": 0, "translation": [1, 0, 0], "children": [1]},
                   {"mesh": 0, "scale": [2, 2, 2]}],
         "buffers": [{"byteLength": len(blob)}],
         "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 36},
                         {"buffer": 0, "byteOffset": 36, "byteLength": 6},
                         {"buffer": 0, "byteOffset": 44, "byteLength": 24}],
         "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                        "min": [0, 0, 0], "max": [1, 1, 0]},
                       {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"},
                       {"bufferView": 2, "componentType": 5126, "count": 3, "type": "VEC2"}],
         "meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 2},
                                     "indices": 1, "material": 0}]}],
         "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [1, 0.5, 0.25, 1]},
                        "alphaMode": "MASK", "doubleSided": True}]}
    if uri is not None:
        g["buffers"][0]["uri"] = uri
    if textured:
        g["images"] = [{"uri": "data:image/png;base64," + base64.b64encode(png_1x1()).decode()}]
        g["samplers"] = [{"magFilter": 9729, "wrapS": 33648}]
        g["textures"] = [{"source": 0, "sampler": 0}]
        g["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"] = {"index": 0}
    return g


embedded = "data:application/octet-stream;base64," + base64.b64encode(blob).decode()
put(d, "embedded.gltf", json.dumps(gltf(embedded)))
put(d, "textured.gltf", json.dumps(gltf(embedded, textured=True)))
external = gltf("buffer.bin")
external["buffers"][0]["byteLength"] = 256
put(d, "external.gltf", json.dumps(external))
escaping = gltf("../../../../etc/hostname")
put(d, "escaping-uri.gltf", json.dumps(escaping))


def glb(g, binary):
    j = json.dumps(g).encode()
    j += b" " * (-len(j) % 4)
    binary += b"\0" * (-len(binary) % 4)
    body = struct.pack("<I4s", len(j), b"JSON") + j + struct.pack("<I4s", len(binary), b"BIN\0") + binary
    return struct.pack("<4sII", b"glTF", 2, 12 + len(body)) + body


put(d, "triangle.glb", glb(gltf(None), blob))

# --- dictionaries for the text formats ---
def words(pattern, paths):
    found = set()
    for p in paths:
        found.update(re.findall(pattern, p.read_text()))
    return sorted(found)


nodes = list((repo / "nodes/volsg/nodes").glob("*.h"))
scene = words(r'typeName = "(\w+)"', nodes) + words(r'\{this, "(\w+)"', nodes)
scene += ["#Inventor V2.1 ascii", "DEF", "USE", "NULL", "fields", "SFFloat", "MFVec3f", "SFNode",
          "MFNode", "SFString", "SFInt32", "SFBool", "TRUE", "FALSE", "UBYTE", "USHORT", "FLOAT",
          "{", "}", "[", "]", "0x7fffffff", "1e39", "nan", "-0"]
(here / "scene.dict").write_text("".join('"%s"\n' % w.replace('"', '\\"') for w in scene))
nrrd_words = ["NRRD0004", "type: ", "dimension: ", "sizes: ", "spacings: ", "encoding: ",
              "endian: ", "data file: ", "datafile: ", "byte skip: ", "line skip: ",
              "space directions: ", "space origin: ", "kinds: ", "raw", "gzip", "gz", "uchar",
              "unsigned short", "short", "float", "big", "little", "data.raw", "data.raw.gz",
              "LIST", "(1,0,0)", "none", "-1"]
(here / "nrrd.dict").write_text("".join('"%s"\n' % w for w in nrrd_words))
meta = ["ObjectType = Image", "NDims = ", "DimSize = ", "ElementType = ", "ElementSpacing = ",
        "ElementSize = ", "ElementDataFile = ", "LOCAL", "LIST", "data.raw", "MET_UCHAR",
        "MET_USHORT", "MET_SHORT", "MET_FLOAT", "MET_DOUBLE", "BinaryData = True",
        "BinaryDataByteOrderMSB = ", "ElementByteOrderMSB = ", "CompressedData = True",
        "CompressedDataSize = ", "HeaderSize = ", "ElementNumberOfChannels = ", "True", "False"]
(here / "metaimage.dict").write_text("".join('"%s"\n' % w for w in meta))
gltf_words = ["asset", "version", "2.0", "scene", "scenes", "nodes", "children", "mesh", "meshes",
              "primitives", "attributes", "POSITION", "NORMAL", "TEXCOORD_0", "TANGENT", "indices",
              "material", "materials", "mode", "targets", "weights", "matrix", "translation",
              "rotation", "scale", "buffers", "bufferViews", "accessors", "buffer", "byteOffset",
              "byteLength", "byteStride", "componentType", "count", "type", "SCALAR", "VEC2",
              "VEC3", "VEC4", "MAT4", "normalized", "sparse", "values", "uri", "images",
              "textures", "samplers", "source", "sampler", "pbrMetallicRoughness",
              "baseColorTexture", "baseColorFactor", "alphaMode", "BLEND", "MASK", "alphaCutoff",
              "doubleSided", "extensionsRequired", "extensionsUsed", "KHR_materials_unlit",
              "KHR_mesh_quantization", "data:application/octet-stream;base64,", "buffer.bin",
              "../", "glTF", "JSON", "BIN\\x00", "5126", "5123", "5125", "5121"]
(here / "gltf.dict").write_text("".join('"%s"\n' % w for w in gltf_words))

# NIfTI: a byte for .nii (0) or .hdr (1), then the file. A 4^3 int16 volume with a qform, a
# gzip uint8 one, and the header of a .hdr/.img pair (its .img does not exist in the scratch
# folder, so that seed ends in the missing-file error).
def nifti(datatype=4, bitpix=16):
    h = bytearray(348)
    struct.pack_into("<i", h, 0, 348)
    struct.pack_into("<8h", h, 40, 3, 4, 4, 4, 1, 1, 1, 1)
    struct.pack_into("<hh", h, 70, datatype, bitpix)
    struct.pack_into("<8f", h, 76, -1.0, 1.5, 1.5, 2.0, 0, 0, 0, 0)
    struct.pack_into("<f", h, 108, 352.0)
    h[123] = 2
    struct.pack_into("<hh", h, 252, 1, 0)
    struct.pack_into("<6f", h, 256, 0.0, 0.0, 0.5, 10, 20, 30)
    h[344:348] = b"n+1\0"
    voxels = struct.pack("<64h", *range(64)) if bitpix == 16 else bytes(range(64))
    return bytes(h) + b"\0" * 4 + voxels


d = folder("nifti")
put(d, "qform-int16", b"\x00" + nifti())
put(d, "uint8-gzip", b"\x00" + gzip.compress(nifti(2, 8), mtime=0))
pair = bytearray(nifti()[:348])
pair[344:348] = b"ni1\0"
put(d, "pair-header", b"\x01" + bytes(pair))

# DICOM: one slice of the derived head CT series (examples/data/derived/make_derived.py).
d = folder("dicom")
put(d, "ct-slice", (repo / "examples/data/derived/headsq_dicom/slice-024.dcm").read_bytes())
