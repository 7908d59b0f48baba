#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Writes the hostile glTF corpus beside this script, and cases.tsv: what the loader
must answer for each file (gltf_loader_test and frusta_bake_cli_test replay them).

The files expect the folder the tests lay out around them (corpus_fixture.h):
  outside.bin, outside.png      beside the input's folder: must never be opened
  in/                           the input's folder, where each file is copied
  in/tetra.bin                  the tetrahedron below
  in/alias.bin -> tetra.bin     a symlink that stays inside
  in/link.bin -> ../outside.bin, in/zero.bin -> /dev/zero
  in/fifo.bin                   a FIFO nobody writes to
  in/sub/                       a folder
  in/huge.bin                   a sparse file one byte over the loader's limit
The 50,000-deep JSON files are made by the tests themselves (too large to keep).

Run it after changing a case; the output is deterministic."""
import base64
import json
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))

# a tetrahedron 5 cm across, wound counter-clockwise seen from outside
POSITIONS = [(0, 0, 0), (0.05, 0, 0), (0, 0.05, 0), (0, 0, 0.05)]
INDICES = [0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3]
TETRA = b"".join(struct.pack("<3f", *p) for p in POSITIONS) + struct.pack("<12H", *INDICES)
assert len(TETRA) == 72
DATA_URI = "data:application/octet-stream;base64," + base64.b64encode(TETRA).decode()
MAX_FILE_BYTES = 512 << 20  # GltfLimits::kMaxFileBytes


def gltf(uri=DATA_URI, byte_length=72, position=None, indices=None, views=None,
         nodes=None, extra=None, binary=False):
    position = position or {}
    indices = indices or {}
    buffer = {"byteLength": byte_length}
    if uri is not None:
        buffer["uri"] = uri
    doc = {
        "asset": {"version": "2.0", "generator": "frusta tests/tools/bake/corpus"},
        "scene": 0,
        "scenes": [{"nodes": [0]}],
        "nodes": nodes or [{"mesh": 0}],
        "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "mode": 4}]}],
        "buffers": [buffer],
        "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                        {"buffer": 0, "byteOffset": 48, "byteLength": 24}] + (views or []),
        "accessors": [dict({"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3"},
                           **position),
                      dict({"bufferView": 1, "componentType": 5123, "count": 12, "type": "SCALAR"},
                           **indices)],
    }
    doc.update(extra or {})
    return doc


def glb(doc, bin_bytes=TETRA, bin_chunk_length=None):
    text = json.dumps(doc).encode()
    text += b" " * (-len(text) % 4)
    out = struct.pack("<II", len(text), 0x4E4F534A) + text
    if bin_bytes is not None:
        padded = bin_bytes + b"\0" * (-len(bin_bytes) % 4)
        length = len(padded) if bin_chunk_length is None else bin_chunk_length
        out += struct.pack("<II", length, 0x004E4942) + padded
    return b"glTF" + struct.pack("<II", 2, 12 + len(out)) + out


def chain(levels, mesh_node_extra=None):
    """levels nodes each listing the next twice, then one with the mesh: 2^levels uses."""
    nodes = [{"children": [i + 1, i + 1]} for i in range(levels)]
    nodes.append(dict({"mesh": 0}, **(mesh_node_extra or {})))
    return nodes


def nested(depth):
    value = 0
    for _ in range(depth):
        value = {"a": value}
    return value


UP = "../" * 12  # more than enough to reach / from any temporary folder

# file, expected result, a fragment of the message (the message always names the file)
CASES = [
    # well-formed: these load
    ("tetra_data_uri.gltf", gltf(), "FRUSTA_OK", ""),
    ("tetra_in_folder.gltf", gltf(uri="tetra.bin"), "FRUSTA_OK", ""),
    ("tetra_symlink_inside.gltf", gltf(uri="alias.bin"), "FRUSTA_OK", ""),
    ("tetra.glb", glb(gltf(uri=None)), "FRUSTA_OK", ""),
    # defect 2: (count - 1) * stride + size wrapped around 2^64 and passed the bound
    ("accessor_count_2p62_position.gltf", gltf(position={"count": 2**62 + 1}),
     "FRUSTA_ERROR_FILE_FORMAT", "POSITION accessor 0 has 4611686018427387905 elements"),
    ("accessor_count_2p62_indices.gltf", gltf(indices={"count": 2**62 + 1, "componentType": 5125}),
     "FRUSTA_ERROR_FILE_FORMAT", "index accessor 1 has 4611686018427387905 elements"),
    ("accessor_count_2p60_stride_16.gltf",
     gltf(position={"count": 2**60 + 1, "bufferView": 2},
          views=[{"buffer": 0, "byteOffset": 0, "byteLength": 48, "byteStride": 16}]),
     "FRUSTA_ERROR_FILE_FORMAT", "POSITION accessor 0 has 1152921504606846977 elements"),
    # defect 3 (the 50,000-deep files are made by the tests): one level over the limit
    ("json_depth_65.gltf", gltf(extra={"extras": nested(64)}),
     "FRUSTA_ERROR_FILE_FORMAT", "JSON nested more than 64 levels deep (in \"extras\")"),
    # defect 4: instancing that multiplies
    ("instancing_2p24_nodes.gltf", gltf(nodes=chain(24)),
     "FRUSTA_ERROR_FILE_FORMAT", "node instances once its nodes are instanced"),
    ("instancing_2p13_meshes_of_4096_triangles.gltf",
     gltf(nodes=chain(13), indices={"count": 3 * 4096}, position={"count": 4}),
     "FRUSTA_ERROR_FILE_FORMAT", "33554432 triangles once its nodes are instanced"),
    ("node_cycle.gltf", gltf(nodes=[{"mesh": 0, "children": [1]}, {"children": [0]}]),
     "FRUSTA_ERROR_FILE_FORMAT", "node 0 is its own descendant"),
    # defect 5: buffers outside the input's folder, or not regular files, or too large
    ("buffer_parent_folder.gltf", gltf(uri="../outside.bin"),
     "FRUSTA_ERROR_FILE_FORMAT", "outside the input's folder"),
    ("buffer_parent_folder_percent_encoded.gltf", gltf(uri="..%2Foutside.bin"),
     "FRUSTA_ERROR_FILE_FORMAT", "outside the input's folder"),
    ("buffer_etc_passwd.gltf", gltf(uri=UP + "etc/passwd"),
     "FRUSTA_ERROR_FILE_FORMAT", "outside the input's folder"),
    ("buffer_proc_self_environ.gltf", gltf(uri=UP + "proc/self/environ"),
     "FRUSTA_ERROR_FILE_FORMAT", "outside the input's folder"),
    ("buffer_dev_zero.gltf", gltf(uri=UP + "dev/zero"),
     "FRUSTA_ERROR_FILE_FORMAT", "outside the input's folder"),
    ("buffer_absolute_path.gltf", gltf(uri="/etc/passwd"),
     "FRUSTA_ERROR_FILE_FORMAT", "File not found"),
    ("buffer_symlink_outside.gltf", gltf(uri="link.bin"),
     "FRUSTA_ERROR_FILE_FORMAT", "outside the input's folder"),
    ("buffer_symlink_dev_zero.gltf", gltf(uri="zero.bin"),
     "FRUSTA_ERROR_FILE_FORMAT", "outside the input's folder"),
    ("buffer_fifo.gltf", gltf(uri="fifo.bin"),
     "FRUSTA_ERROR_FILE_FORMAT", "not a regular file"),
    ("buffer_folder.gltf", gltf(uri="sub"),
     "FRUSTA_ERROR_FILE_FORMAT", "not a regular file"),
    ("buffer_over_the_size_limit.gltf", gltf(uri="huge.bin", byte_length=MAX_FILE_BYTES + 1),
     "FRUSTA_ERROR_FILE_FORMAT", "bytes the loader reads"),
    ("glb_buffer_parent_folder.glb", glb(gltf(uri="../outside.bin"), bin_bytes=None),
     "FRUSTA_ERROR_FILE_FORMAT", "outside the input's folder"),
    # a BIN chunk 8 bytes longer than the file (tinygltf read past the end)
    ("glb_bin_chunk_past_the_end.glb", glb(gltf(uri=None, byte_length=80), bin_chunk_length=80),
     "FRUSTA_ERROR_FILE_FORMAT", "BIN chunk of 80 bytes runs past its end"),
    # images are never opened nor decoded: these load, and nothing outside is touched
    ("image_parent_folder.gltf", gltf(extra={"images": [{"uri": "../outside.png"}]}),
     "FRUSTA_OK", ""),
    ("image_fifo.gltf", gltf(extra={"images": [{"uri": "fifo.bin"}]}), "FRUSTA_OK", ""),
    ("image_buffer_view_past_the_end.gltf",
     gltf(views=[{"buffer": 0, "byteOffset": 1000000000, "byteLength": 64}],
          extra={"images": [{"bufferView": 2, "mimeType": "image/png"}]}),
     "FRUSTA_OK", ""),
    ("glb_image_parent_folder.glb", glb(gltf(uri=None, extra={"images": [{"uri": "../outside.png"}]})),
     "FRUSTA_OK", ""),
]


def main():
    names = set()
    with open(os.path.join(HERE, "cases.tsv"), "w") as manifest:
        manifest.write("# file\texpected result\tfragment of the message (written by make_corpus.py)\n")
        for name, content, result, fragment in CASES:
            assert name not in names
            names.add(name)
            data = content if isinstance(content, bytes) else (json.dumps(content, indent=1) + "\n").encode()
            with open(os.path.join(HERE, name), "wb") as f:
                f.write(data)
            manifest.write(f"{name}\t{result}\t{fragment}\n")
    for stale in os.listdir(HERE):
        if stale.endswith((".gltf", ".glb")) and stale not in names:
            os.remove(os.path.join(HERE, stale))


if __name__ == "__main__":
    main()
