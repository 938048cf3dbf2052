#!/usr/bin/env python3
"""Writes the fuzz seed corpora in fuzz/corpus/<target>/ from the headers in ../shared/data.

Each seed keeps a real header's text but shrinks its sizes to a few voxels and carries its own
small data (attached, or as "--ewa-fuzz-file--" sections that the harness writes to data.0,
data.1, ...), so seeds are tiny and still reach the data-reading code. Run it again when the
shared data or the harness's input format changes; the output is deterministic.
"""
import base64
import bz2
import os
import re
import struct
import sys
import zlib
import gzip
import io
import tarfile
import zipfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DATA = os.path.join(ROOT, "..", "shared", "data")
OUT = os.path.join(ROOT, "fuzz", "corpus")
MARK = b"\n--ewa-fuzz-file--\n"
SIZES = (4, 3, 2)
TYPE_BYTES = {"uchar": 1, "uint8_t": 1, "uint8": 1, "char": 1, "short": 2, "int16": 2,
              "ushort": 2, "uint16": 2, "float": 4, "float32": 4, "met_uchar": 1,
              "met_char": 1, "met_short": 2, "met_ushort": 2, "met_float": 4}


def payload(count, width, seed):
    # Deterministic bytes; for floats, finite values plus one NaN and one infinity.
    if width == 4:
        vals = [float((i * 37 + seed) % 200) for i in range(count)]
        if count > 2:
            vals[1] = float("nan")
            vals[2] = float("inf")
        return struct.pack("<%df" % count, *vals)
    return bytes(((i * 53 + seed * 7) % 251) for i in range(count * width))


def write(target, name, data):
    folder = os.path.join(OUT, target)
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)


def read_text(path):
    with open(path, "rb") as f:
        return f.read()


def nrrd_header_lines(raw):
    end = raw.find(b"\n\n")
    head = raw if end < 0 else raw[:end]
    return head.decode("latin-1").split("\n")


def shrink_nrrd(lines, data_file):
    out, type_name, encoding, dim = [], "uchar", "raw", 3
    for line in lines:
        key = line.split(":", 1)[0].strip().lower().replace(" ", "")
        if key == "type":
            type_name = line.split(":", 1)[1].strip().lower()
        if key == "encoding":
            encoding = line.split(":", 1)[1].strip().lower()
        if key == "dimension":
            dim = int(line.split(":", 1)[1])
        if key == "sizes":
            line = "sizes: " + " ".join(str(s) for s in SIZES[:dim])
        if key in ("datafile", "data file") or key == "datafile":
            if data_file is None:
                continue
            line = "data file: " + data_file
        out.append(line)
    return out, TYPE_BYTES.get(type_name, 1), encoding


def nrrd_seeds():
    n = SIZES[0] * SIZES[1] * SIZES[2]
    for rel in ["engine/engine.nhdr", "cthead/CThead.nhdr", "headsq/quarter.nhdr",
                "nucleon/nucleon.nrrd", "tooth/tooth.nrrd", "fetal-t2/template_T2.nrrd"]:
        path = os.path.join(DATA, rel)
        if not os.path.exists(path):
            continue
        lines = nrrd_header_lines(read_text(path))
        name = os.path.basename(rel)
        detached = any(l.lower().replace(" ", "").startswith("datafile:") for l in lines)
        pattern = "%d" in "".join(lines)
        data_file = ("data.%d 0 1 1" if pattern else "data.0") if detached else None
        header, width, encoding = shrink_nrrd(lines, data_file)
        body = payload(n, width, len(name))
        if encoding in ("gzip", "gz"):
            body = gzip.compress(body, mtime=0)
        text = ("\n".join(header) + "\n").encode()
        if not detached:
            write("nrrd", name, text + b"\n" + body)
        elif pattern:
            half = len(body) // 2
            write("nrrd", name, text + MARK + body[:half] + MARK + body[half:])
        else:
            write("nrrd", name, text + MARK + body)
    # A tilted gantry's sheared axes: the loaders resample such a grid within each slice.
    tilt = ("NRRD0004\ntype: short\ndimension: 3\nspace: left-posterior-superior\n"
            "sizes: 4 3 2\nspace directions: (0.5,0,0) (0,0.5,0) (0,0.3,1.2)\n"
            "space origin: (0,0,0)\nencoding: raw\nendian: little\n\n").encode()
    write("nrrd", "tilt.nrrd", tilt + payload(n, 2, 7))
    # 4D: time points last (--frame) and colour first (--channel).
    time = ("NRRD0004\ntype: uchar\ndimension: 4\nsizes: 4 3 2 3\n"
            "space directions: (1,0,0) (0,1,0) (0,0,1) none\n"
            "kinds: domain domain domain list\nencoding: raw\n\n").encode()
    write("nrrd", "time4d.nrrd", time + payload(3 * n, 1, 8))
    rgb = ("NRRD0004\ntype: uchar\ndimension: 4\nsizes: 3 4 3 2\n"
           "kinds: RGB-color domain domain domain\nencoding: raw\n\n").encode()
    write("nrrd", "rgb4d.nrrd", rgb + payload(3 * n, 1, 9))
    # The other encodings (bzip2, ASCII, hex) and a wide type made float32.
    def small(type_name, encoding, extra=""):
        return ("NRRD0005\ntype: %s\ndimension: 3\nsizes: %d %d %d\nencoding: %s\n%s\n"
                % ((type_name,) + SIZES + (encoding, extra))).encode()
    write("nrrd", "bzip2.nrrd", small("ushort", "bzip2", "endian: big\n")
          + bz2.compress(payload(n, 2, 10)))
    write("nrrd", "ascii.nrrd", small("short", "ascii")
          + " ".join(str((i * 37) % 500 - 250) for i in range(n)).encode() + b"\n")
    write("nrrd", "hex.nrrd", small("float", "hex", "endian: little\n")
          + payload(n, 4, 11).hex().encode() + b"\n")
    write("nrrd", "double.nrrd", small("double", "raw", "endian: little\n")
          + struct.pack("<%dd" % n, *[float(i * 3 - 10) for i in range(n)]))


def metaimage_seeds():
    n = SIZES[0] * SIZES[1] * SIZES[2]
    for rel in ["headmr/HeadMRVolume.mhd", "lidc2/LIDC2.mha"]:
        path = os.path.join(DATA, rel)
        if not os.path.exists(path):
            continue
        raw = read_text(path)
        end = raw.find(b"ElementDataFile")
        end = raw.find(b"\n", end) + 1
        lines = raw[:end].decode("latin-1").split("\n")
        width, compressed, local, out = 1, False, False, []
        for line in lines:
            key = line.split("=", 1)[0].strip().lower()
            value = line.split("=", 1)[1].strip() if "=" in line else ""
            if key == "dimsize":
                line = "DimSize = %d %d %d" % SIZES
            if key == "elementtype":
                width = TYPE_BYTES.get(value.lower(), 1)
            if key == "compresseddata":
                compressed = value.lower() == "true"
            if key == "elementdatafile":
                local = value.upper() == "LOCAL"
                if not local:
                    line = "ElementDataFile = data.0"
            out.append(line)
        body = payload(n, width, len(rel))
        if compressed:
            body = zlib.compress(body)
            out = [("CompressedDataSize = %d" % len(body))
                   if l.lower().startswith("compresseddatasize") else l for l in out]
        text = "\n".join(out).encode()
        name = os.path.basename(rel)
        write("metaimage", name, text + body if local else text + MARK + body)
    # A plain LOCAL uncompressed short volume as well.
    text = ("ObjectType = Image\nNDims = 3\nDimSize = %d %d %d\nElementSpacing = 1 1 2\n"
            "ElementType = MET_SHORT\nElementByteOrderMSB = True\nElementDataFile = LOCAL\n" % SIZES)
    write("metaimage", "local_short.mha", text.encode() + payload(n, 2, 3))


def dat_seeds():
    n = SIZES[0] * SIZES[1] * SIZES[2]
    for rel in ["hydrogen/hydrogenatom.dat", "walnut/walnut.dat", "nucleon/nucleon.dat"]:
        path = os.path.join(DATA, rel)
        if not os.path.exists(path):
            continue
        out, width = [], 1
        for line in read_text(path).decode("latin-1").split("\n"):
            key = line.split(":", 1)[0].strip().lower()
            value = line.split(":", 1)[1].strip() if ":" in line else ""
            if key == "objectfilename":
                line = "ObjectFileName:\tdata.0"
            if key == "resolution":
                line = "Resolution:\t%d %d %d" % SIZES
            if key == "format":
                width = TYPE_BYTES.get(value.lower(), 1)
            out.append(line)
        write("dat", os.path.basename(rel), "\n".join(out).encode() + MARK + payload(n, width, 5))


def vti_seeds():
    n = SIZES[0] * SIZES[1] * SIZES[2]
    path = os.path.join(DATA, "engine", "engine.vti")
    if not os.path.exists(path):
        return
    raw = read_text(path)
    head = raw[:raw.find(b"_", raw.find(b"<AppendedData")) + 1].decode("latin-1")
    extent = "0 %d 0 %d 0 %d" % (SIZES[0] - 1, SIZES[1] - 1, SIZES[2] - 1)
    head = re.sub(r'Extent="[^"]*"', 'Extent="%s"' % extent, head)
    body = payload(n, 1, 9)
    # zlib blocks with UInt64 headers, as the original: 2 blocks.
    block = 16
    blocks = [body[i:i + block] for i in range(0, len(body), block)]
    packed = [zlib.compress(b) for b in blocks]
    table = struct.pack("<QQQ", len(blocks), block, len(blocks[-1]) % block)
    table += b"".join(struct.pack("<Q", len(p)) for p in packed)
    tail = "\n  </AppendedData>\n</VTKFile>\n".encode()
    write("vti", "engine_zlib.vti", head.encode() + table + b"".join(packed) + tail)
    # Uncompressed appended raw, UInt32 header.
    plain = head.replace(' compressor="vtkZLibDataCompressor"', "").replace("UInt64", "UInt32")
    write("vti", "appended_raw.vti", plain.encode() + struct.pack("<I", n) + body + tail)
    # Inline base64, Int16, big endian.
    body16 = payload(n, 2, 4)
    b64 = base64.b64encode(struct.pack(">I", len(body16)) + body16).decode()
    inline = ('<?xml version="1.0"?>\n<VTKFile type="ImageData" version="1.0" '
              'byte_order="BigEndian" header_type="UInt32">\n'
              '  <ImageData WholeExtent="%s" Origin="1 2 3" Spacing="0.5 1 2">\n'
              '    <Piece Extent="%s">\n      <PointData Scalars="s">\n'
              '        <DataArray type="Int16" Name="s" format="binary">%s</DataArray>\n'
              '      </PointData>\n    </Piece>\n  </ImageData>\n</VTKFile>\n' % (extent, extent, b64))
    write("vti", "inline_base64.vti", inline.encode())
    # Inline ASCII numbers, Float64 (made float32).
    numbers = " ".join("%g" % (i * 0.5 - 3) for i in range(n))
    ascii_text = inline.replace('type="Int16" Name="s" format="binary">%s' % b64,
                                'type="Float64" Name="s" format="ascii">%s' % numbers)
    write("vti", "inline_ascii.vti", ascii_text.encode())


def raw_seeds():
    n = SIZES[0] * SIZES[1] * SIZES[2]
    dims = "%d,%d,%d" % SIZES
    for name, opts, width in [("uint8", [dims, "uint8", "", ""], 1),
                              ("uint16_big", [dims, "uint16", "1,1,2", "big"], 2),
                              ("float32", [dims, "float32", "0.5", "little"], 4),
                              ("int16", [dims.replace(",", "x"), "short", "1 2 3", "le"], 2),
                              ("float64_big", [dims, "float64", "", "big"], 8)]:
        write("raw", name, "\n".join(opts).encode() + MARK + payload(n, width, 1))


def tf_seeds():
    for rel in ["assets/default.tf.json", "assets/presets/bonsai.tf.json"]:
        path = os.path.join(ROOT, rel)
        if os.path.exists(path):
            write("tf_json", os.path.basename(rel), read_text(path))
    write("tf_json", "minimal.json", b'{"opacity": [[0, 0], [255, 1]]}')
    write("tf_json", "step.json",
          b'{"opacity": [[0, 0], [10, 0], [10, 0.5]], "color": [[0, 1, 0, 0], [10, 0, 0, 1]],'
          b' "opacity_unit_distance": 0.25, "name": "step"}')


def nifti_seeds():
    # Real headers with the sizes cut to 4 x 3 x 2 (4D: 2 frames) and data of their type.
    for rel in ["nifti/anatomical.nii", "nifti/functional.nii", "nifti/example4d.nii.gz",
                "nifti/example_nifti2.nii.gz", "nifti/standard.nii.gz"]:
        raw = read_text(os.path.join(DATA, rel))
        if rel.endswith(".gz"):
            raw = gzip.decompress(raw)
        big = struct.unpack("<i", raw[:4])[0] not in (348, 540)
        e = ">" if big else "<"
        nifti2 = struct.unpack(e + "i", raw[:4])[0] == 540
        head = bytearray(raw[:544 if nifti2 else 352])
        if nifti2:
            dims = list(struct.unpack(e + "8q", head[16:80]))
            datatype, bitpix = struct.unpack(e + "2h", head[12:16])
        else:
            dims = list(struct.unpack(e + "8h", head[40:56]))
            datatype, bitpix = struct.unpack(e + "2h", head[70:74])
        frames = 2 if dims[0] >= 4 else 1
        dims[1:5] = [SIZES[0], SIZES[1], SIZES[2], frames]
        if nifti2:
            head[16:80] = struct.pack(e + "8q", *dims)
            head[168:176] = struct.pack(e + "q", len(head))
        else:
            head[40:56] = struct.pack(e + "8h", *dims)
            head[108:112] = struct.pack(e + "f", float(len(head)))
        body = payload(SIZES[0] * SIZES[1] * SIZES[2] * frames, max(1, bitpix // 8), 3)
        out = bytes(head) + body
        name = os.path.basename(rel)
        write("nifti", name, gzip.compress(out, mtime=0) if rel.endswith(".gz") else out)


def dicom_elements(raw):
    # (tag, value offset, length) of the top-level elements of an implicit VR little-endian
    # data set after the explicit-VR group 2 meta header; enough to rewrite sizes in a seed.
    pos, out = 132, []
    while pos < len(raw):
        group, elem = struct.unpack("<HH", raw[pos:pos + 4])
        if group == 2:
            vr = raw[pos + 4:pos + 6]
            if vr in (b"OB", b"OW", b"SQ", b"UN", b"UT"):
                length = struct.unpack("<I", raw[pos + 8:pos + 12])[0]
                start = pos + 12
            else:
                length = struct.unpack("<H", raw[pos + 6:pos + 8])[0]
                start = pos + 8
        else:
            length = struct.unpack("<I", raw[pos + 4:pos + 8])[0]
            start = pos + 8
            if length == 0xFFFFFFFF:
                end = raw.find(b"\xfe\xff\xdd\xe0", pos)
                out.append(((group, elem), start, end - start))
                pos = end + 8
                continue
        out.append(((group, elem), start, length))
        pos = start + length
    return out


def small_dicom(raw, z, rows=3, cols=4):
    # A PET slice shrunk to cols x rows pixels, moved to height z.
    out = bytearray()
    last = 0
    for tag, start, length in dicom_elements(raw):
        value = None
        if tag == (0x0028, 0x0010):
            value = struct.pack("<H", rows)
        elif tag == (0x0028, 0x0011):
            value = struct.pack("<H", cols)
        elif tag == (0x0020, 0x0032):
            value = ("0\\0\\%g" % z).encode()
            value += b" " * (len(value) % 2)
        elif tag == (0x7FE0, 0x0010):
            value = payload(rows * cols, 2, int(z))
        if value is None:
            continue
        out += raw[last:start - 4] + struct.pack("<I", len(value)) + value
        last = start + length
    out += raw[last:]
    return bytes(out)


def without_meta(raw):
    # The data set alone, as ACR-NEMA files hold it: no preamble, no group 2 meta header.
    elements = dicom_elements(raw)
    first = next(start for tag, start, length in elements if tag[0] != 2)
    return raw[first - 8:]


EXPLICIT_LE = b"1.2.840.10008.1.2.1"
DEFLATED = b"1.2.840.10008.1.2.1.99"


def explicit_element(group, elem, vr, value):
    # One explicit VR little-endian element, its value padded to even length.
    if len(value) % 2:
        value += b"\0" if vr == b"UI" else b" "
    if vr in (b"OB", b"OW", b"SQ", b"UN", b"UT"):
        return struct.pack("<HH2s2xI", group, elem, vr, len(value)) + value
    return struct.pack("<HH2sH", group, elem, vr, len(value)) + value


def undefined_length(group, elem, vr):
    return struct.pack("<HH2s2xI", group, elem, vr, 0xFFFFFFFF)


def nested_sequences(depth):
    # `depth` undefined-length Content Sequences, each the one item of the one above.
    item, item_end, seq_end = (struct.pack("<HHI", 0xFFFE, e, length) for e, length in
                               ((0xE000, 0xFFFFFFFF), (0xE00D, 0), (0xE0DD, 0)))
    return ((undefined_length(0x0040, 0xA730, b"SQ") + item) * depth +
            explicit_element(0x0040, 0xA160, b"UT", b"deep") + (item_end + seq_end) * depth)


def explicit_image(z, extra=b"", rows=3, cols=4, first=b"", before_series=b"", pixels=None):
    # A small secondary-capture image data set in explicit VR little endian, in tag order:
    # `first` before (0008,0016), `before_series` before (0020,000E), `extra` (elements of
    # groups 0029 to 7FDF) before its pixels.
    e = explicit_element
    return (first + e(0x0008, 0x0016, b"UI", b"1.2.840.10008.5.1.4.1.1.7") +
            e(0x0008, 0x0018, b"UI", b"1.2.826.0.1.3680043.2.1125.77.1") +
            e(0x0008, 0x0060, b"CS", b"OT") + before_series +
            e(0x0020, 0x000E, b"UI", b"1.2.826.0.1.3680043.2.1125.77") +
            e(0x0020, 0x0032, b"DS", ("0\\0\\%g" % z).encode()) +
            e(0x0020, 0x0037, b"DS", b"1\\0\\0\\0\\1\\0") +
            e(0x0028, 0x0002, b"US", struct.pack("<H", 1)) +
            e(0x0028, 0x0004, b"CS", b"MONOCHROME2") +
            e(0x0028, 0x0010, b"US", struct.pack("<H", rows)) +
            e(0x0028, 0x0011, b"US", struct.pack("<H", cols)) +
            e(0x0028, 0x0030, b"DS", b"0.5\\0.5") +
            e(0x0028, 0x0100, b"US", struct.pack("<H", 16)) +
            e(0x0028, 0x0101, b"US", struct.pack("<H", 16)) +
            e(0x0028, 0x0102, b"US", struct.pack("<H", 15)) +
            e(0x0028, 0x0103, b"US", struct.pack("<H", 0)) + extra +
            e(0x7FE0, 0x0010, b"OW", payload(rows * cols, 2, int(z)) if pixels is None else pixels))


def csa_header(elements):
    # A Siemens CSA header in syngo's SV10 format: (name, [values]) elements of IS values.
    out = b"SV10\4\3\2\1" + struct.pack("<II", len(elements), 77)
    for name, values in elements:
        out += struct.pack("<64si4s3i", name.encode(), len(values), b"IS", 6, len(values), 77)
        for v in values:
            t = v.encode() + b"\0"
            out += struct.pack("<4i", len(t), len(t), 77, len(t)) + t + b"\0" * (-len(t) % 4)
    return out


def mosaic_image():
    # A Siemens mosaic: 4 slices of 2 x 2 in 2 x 2 tiles, as the CSA header counts them.
    e = explicit_element
    csa = csa_header([("NumberOfImagesInMosaic", ["4"]), ("SliceNormalVector", ["0", "0", "1"])])
    return explicit_image(0, rows=4, cols=4, pixels=payload(16, 2, 5),
                          first=e(0x0008, 0x0008, b"CS", b"ORIGINAL\\PRIMARY\\M\\MOSAIC"),
                          before_series=e(0x0018, 0x0088, b"DS", b"3"),
                          extra=e(0x0029, 0x0010, b"LO", b"SIEMENS CSA HEADER") +
                          e(0x0029, 0x1010, b"OB", csa))


def part10(data_set, syntax):
    # Preamble and meta header (its group length first) before `data_set`.
    e = explicit_element
    meta = (e(0x0002, 0x0001, b"OB", b"\0\1") +
            e(0x0002, 0x0002, b"UI", b"1.2.840.10008.5.1.4.1.1.7") +
            e(0x0002, 0x0003, b"UI", b"1.2.826.0.1.3680043.2.1125.77.1") +
            e(0x0002, 0x0010, b"UI", syntax))
    return b"\0" * 128 + b"DICM" + e(0x0002, 0x0000, b"UL", struct.pack("<I", len(meta))) + meta + \
        data_set


def raw_deflate(data):
    # The deflated syntax's stream: raw deflate, no zlib header or trailer.
    c = zlib.compressobj(9, zlib.DEFLATED, -15)
    return c.compress(data) + c.flush()


def dicom_seeds():
    pet = read_text(os.path.join(DATA, "dicom-pet", "000000.dcm"))
    write("dicom", "pet_slice.dcm", small_dicom(pet, 0))
    write("dicom", "bare_implicit_slice.dcm", without_meta(small_dicom(pet, 0)))
    write("dicom", "pet_three_slices.dcm",
          small_dicom(pet, 0) + MARK + small_dicom(pet, 3.375) + MARK + small_dicom(pet, 6.75))
    # The classes hostile files came in: zero padding after the last element (legal), nesting
    # past the pre-check's limit (refused), a deflated data set (inflated and walked).
    write("dicom", "pet_slice_zero_padded.dcm", small_dicom(pet, 0) + bytes(1000))
    write("dicom", "nested_200_deep.dcm", part10(explicit_image(0, nested_sequences(200)),
                                                 EXPLICIT_LE))
    write("dicom", "deflated_slice.dcm", part10(raw_deflate(explicit_image(0)), DEFLATED))
    write("dicom", "siemens_mosaic.dcm", part10(mosaic_image(), EXPLICIT_LE))
    # The deflating target's inputs are inflated data sets (it deflates them into a file).
    write("dicom_deflate", "slice.bin", explicit_image(0))
    write("dicom_deflate", "slice_nested_20.bin", explicit_image(0, nested_sequences(20)))
    write("dicom_deflate", "slice_zero_padded.bin", explicit_image(0) + bytes(3))


def tiff_file(pages, bits, sample_format, description=b""):
    # A little-endian TIFF: one strip per page, width 4, height 3, one sample.
    width, height = SIZES[0], SIZES[1]
    out = bytearray(b"II*\0" + struct.pack("<I", 0))
    ifd_offsets = []
    for p in range(pages):
        data = payload(width * height, bits // 8, p) if sample_format != 3 else \
            struct.pack("<%df" % (width * height), *[float(i + p) for i in range(width * height)])
        data_at = len(out)
        out += data
        desc_at = len(out)
        out += description + b"\0" if description and p == 0 else b""
        if len(out) % 2:
            out += b"\0"
        entries = [(256, 4, 1, width), (257, 4, 1, height), (258, 3, 1, bits), (259, 3, 1, 1),
                   (262, 3, 1, 1), (273, 4, 1, data_at), (277, 3, 1, 1), (278, 4, 1, height),
                   (279, 4, 1, len(data)), (339, 3, 1, sample_format)]
        if description and p == 0:
            entries.append((270, 2, len(description) + 1, desc_at))
        entries.sort()
        ifd_offsets.append(len(out))
        out += struct.pack("<H", len(entries))
        for tag, typ, count, value in entries:
            if typ == 3 and count == 1:
                out += struct.pack("<HHIHH", tag, typ, count, value, 0)
            else:
                out += struct.pack("<HHII", tag, typ, count, value)
        out += struct.pack("<I", 0)
    out[4:8] = struct.pack("<I", ifd_offsets[0])
    for a, b in zip(ifd_offsets, ifd_offsets[1:]):
        count = struct.unpack("<H", out[a:a + 2])[0]
        out[a + 2 + 12 * count:a + 6 + 12 * count] = struct.pack("<I", b)
    return bytes(out)


def tiff_seeds():
    write("tiff", "uint8_pages.tif", tiff_file(2, 8, 1))
    write("tiff", "uint16_imagej.tif",
          tiff_file(2, 16, 1, b"ImageJ=1.53\nimages=2\nslices=2\nunit=micron\nspacing=2.5\n"))
    write("tiff", "float32.tif", tiff_file(2, 32, 3))
    # Channels and time points: an ImageJ hyperstack and an OME-TIFF (Z fastest).
    write("tiff", "hyperstack.tif",
          tiff_file(4, 8, 1, b"ImageJ=1.53\nimages=4\nchannels=2\nslices=1\nframes=2\n"))
    write("tiff", "planes.ome.tif",
          tiff_file(4, 16, 1, b'<OME><Image><Pixels DimensionOrder="XYZCT" SizeZ="2" SizeC="2" '
                    b'SizeT="1" PhysicalSizeX="0.5" PhysicalSizeZ="2" PhysicalSizeZUnit="mm"/>'
                    b'</Image></OME>'))
    # A dataset over two files: this one (the harness names it in.tif) holds time point 0, a
    # file that is not there time point 1.
    write("tiff", "files.ome.tif",
          tiff_file(4, 16, 1, b'<OME><Image><Pixels DimensionOrder="XYZCT" SizeZ="2" SizeC="2" '
                    b'SizeT="2"><TiffData PlaneCount="4"><UUID FileName="in.tif">urn:uuid:a'
                    b'</UUID></TiffData><TiffData FirstT="1" IFD="0"><UUID FileName="t1.ome.tif"/>'
                    b'</TiffData></Pixels></Image></OME>'))
    # Bio-Formats' companion form: the metadata in another file, here not there.
    write("tiff", "binary_only.ome.tif",
          tiff_file(2, 8, 1, b'<OME><BinaryOnly MetadataFile="set.companion.ome" UUID="urn:uuid:a"/>'
                    b'</OME>'))


def slc_seeds():
    # neghip.slc's header with 4 x 3 x 2 voxels: raw slices, and run-length encoded ones.
    head = read_text(os.path.join(DATA, "neghip", "neghip.slc"))[:48].split(b"\n")
    lines = head[:4]
    lines[1] = b"%d %d %d 8" % SIZES
    icon = b"2 2 X" + bytes(12)
    plane = SIZES[0] * SIZES[1]
    write("slc", "raw.slc", b"\n".join(lines[:3] + [b"1 6 0 0"]) + b"\n" + icon +
          payload(plane * SIZES[2], 1, 5))
    rle = b""
    for z in range(SIZES[2]):
        body = bytes([0x80 | 4]) + payload(4, 1, z) + bytes([plane - 4, 9, 0])
        rle += b"%d X" % len(body) + body
    write("slc", "rle.slc", b"\n".join(lines[:3] + [b"1 6 0 1"]) + b"\n" + icon + rle)


def mrc_file(mode, data, big=False, axes=(1, 2, 3), extended=b"", origin=(0.0, 0.0, 0.0),
             imod=False):
    # An MRC2014 header for SIZES voxels (cell = sizes: spacing 1), then `extended`, then `data`.
    e = ">" if big else "<"
    words = [0] * 256
    words[0:4] = [SIZES[0], SIZES[1], SIZES[2], mode]
    words[7:10] = list(SIZES)
    words[16:19] = list(axes)
    words[23] = len(extended)
    if imod:
        words[38] = 1146047817
    head = bytearray(struct.pack(e + "256i", *words))
    struct.pack_into(e + "3f", head, 40, *[float(s) for s in SIZES])
    struct.pack_into(e + "3f", head, 196, *origin)
    head[208:212] = b"MAP "
    head[212:214] = b"\x11\x11" if big else b"\x44\x44"
    return bytes(head) + extended + data


def mrc_seeds():
    n = SIZES[0] * SIZES[1] * SIZES[2]
    write("mrc", "float32.mrc", mrc_file(2, payload(n, 4, 1)))
    write("mrc", "int16_big.map", mrc_file(1, payload(n, 2, 2), big=True, origin=(5.0, -2.0, 1.5)))
    write("mrc", "imod_bytes.rec", mrc_file(0, payload(n, 1, 3), imod=True, axes=(3, 1, 2)))
    write("mrc", "half_extended.mrc", mrc_file(12, payload(n, 2, 4), extended=b"\0" * 16))


def vtk_seeds():
    # Legacy VTK structured points as VTK writes them: ASCII floats, big-endian binary shorts and
    # doubles, and an unsigned char image as COLOR_SCALARS.
    n = SIZES[0] * SIZES[1] * SIZES[2]
    def head(encoding, scalars):
        return (b"# vtk DataFile Version 5.1\nvtk output\n" + encoding +
                b"\nDATASET STRUCTURED_POINTS\nDIMENSIONS %d %d %d\nSPACING 1 2 0.5\n"
                b"ORIGIN 3 -1 0\nPOINT_DATA %d\n" % (SIZES + (n,)) + scalars + b"\n")
    lut = b"\nLOOKUP_TABLE default"
    write("vtk", "ascii_float.vtk",
          head(b"ASCII", b"SCALARS v float" + lut) +
          b" ".join(b"%g" % (0.5 * i) for i in range(n)) + b"\n")
    write("vtk", "binary_short.vtk",
          head(b"BINARY", b"SCALARS v short 1" + lut) + struct.pack(">%dh" % n, *range(-5, n - 5)))
    write("vtk", "binary_double.vtk",
          head(b"BINARY", b"SCALARS v double" + lut) + struct.pack(">%dd" % n, *[i * 0.25 for i in range(n)]))
    write("vtk", "color_bytes.vtk", head(b"BINARY", b"COLOR_SCALARS ImageFile 1") + payload(n, 1, 5))


def zip_bytes(entries):
    # Fixed dates, so the output stays deterministic.
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as z:
        for name, data in entries:
            z.writestr(zipfile.ZipInfo(name, date_time=(2026, 1, 1, 0, 0, 0)), data,
                       zipfile.ZIP_DEFLATED)
    return out.getvalue()


def tar_bytes(entries, gz):
    out = io.BytesIO()
    with tarfile.open(fileobj=out, mode="w", format=tarfile.USTAR_FORMAT) as t:
        for name, data in entries:
            info = tarfile.TarInfo(name)
            info.size, info.mtime = len(data), 0
            t.addfile(info, io.BytesIO(data))
    data = out.getvalue()
    return gzip.compress(data, mtime=0) if gz else data


def archive_seeds():
    # Archives as downloads come: a volume file with its header, a detached header and its data,
    # a DICOM series in a folder; the harness writes each as in.zip (libarchive reads any format).
    tooth = read_text(os.path.join(OUT, "nrrd", "tooth.nrrd"))
    write("archive", "nrrd.zip", zip_bytes([("scan/", b""), ("scan/tooth.nrrd", tooth)]))
    head = b"NRRD0004\ntype: uint8\ndimension: 3\nsizes: 4 3 2\nencoding: raw\ndata file: v.raw\n"
    write("archive", "detached.tar",
          tar_bytes([("v/v.nhdr", head), ("v/v.raw", payload(24, 1, 5))], gz=False))
    pet = read_text(os.path.join(DATA, "dicom-pet", "000000.dcm"))
    write("archive", "dicom.tar.gz",
          tar_bytes([("series/a.dcm", small_dicom(pet, 0)), ("series/b.dcm", small_dicom(pet, 3.375))],
                    gz=True))


def png_bytes(width, height, colour_type, bits, samples):
    # Filter 0 rows of big-endian samples; the chunks' CRCs as PNG wants them.
    per = {0: 1, 2: 3, 4: 2, 6: 4}[colour_type] * width
    rows = b""
    for y in range(height):
        row = samples[y * per:(y + 1) * per]
        rows += b"\0" + (struct.pack(">%dH" % per, *row) if bits == 16 else bytes(row))

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(
            ">I", zlib.crc32(kind + data) & 0xffffffff)
    ihdr = struct.pack(">IIBBBBB", width, height, bits, colour_type, 0, 0, 0)
    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", zlib.compress(rows))
            + chunk(b"IEND", b""))


# Two JPEGs of 4 x 3 pixels made once with ImageMagick (grey baseline; colour progressive).
JPEG_GREY = ("/9j/4AAQSkZJRgABAQAAAQABAAD/2wBDAAMCAgMCAgMDAwMEAwMEBQgFBQQEBQoHBwYIDAoMDAsKCwsNDhIQDQ4R"
             "DgsLEBYQERMUFRUVDA8XGBYUGBIUFRT/wAALCAADAAQBAREA/8QAFAABAAAAAAAAAAAAAAAAAAAACP/EABsQAAAH"
             "AQAAAAAAAAAAAAAAAAACBggYV5PS/9oACAEBAAA/AGnAFu9TJ/I/Q//Z")
JPEG_COLOUR = ("/9j/4AAQSkZJRgABAQAAAQABAAD/2wBDAAMCAgMCAgMDAwMEAwMEBQgFBQQEBQoHBwYIDAoMDAsKCwsNDhIQDQ4R"
               "DgsLEBYQERMUFRUVDA8XGBYUGBIUFRT/2wBDAQMEBAUEBQkFBQkUDQsNFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQU"
               "FBQUFBQUFBQUFBQUFBQUFBQUFBQUFBQUFBT/wgARCAADAAQDAREAAhEBAxEB/8QAFAABAAAAAAAAAAAAAAAAAAAA"
               "B//EABUBAQEAAAAAAAAAAAAAAAAAAAQH/9oADAMBAAIQAxAAAAEHv6f/xAAWEAADAAAAAAAAAAAAAAAAAAAAAxT/"
               "2gAIAQEAAQUCrcf/xAAYEQACAwAAAAAAAAAAAAAAAAAAAgUWVP/aAAgBAwEBPwGyy+hj/8QAGBEAAgMAAAAAAAAA"
               "AAAAAAAAAAIFFlT/2gAIAQIBAT8BqsJlU//EABYQAAMAAAAAAAAAAAAAAAAAAAABM//aAAgBAQAGPwKjP//EABQQ"
               "AQAAAAAAAAAAAAAAAAAAAAD/2gAIAQEAAT8hT//aAAwDAQACAAMAAAAQH//EABcRAAMBAAAAAAAAAAAAAAAAAAAB"
               "0fH/2gAIAQMBAT8Q1lD/xAAXEQADAQAAAAAAAAAAAAAAAAAAAdHx/9oACAECAQE/EMh0/8QAFhAAAwAAAAAAAAAA"
               "AAAAAAAAAAHx/9oACAEBAAE/ELiP/9k=")


def image_seeds():
    # One slice each (the harness names the input .png; stb_image goes by content).
    w, h = 4, 3
    grey = [(i * 37) % 256 for i in range(w * h)]
    write("image", "grey8.png", png_bytes(w, h, 0, 8, grey))
    write("image", "grey16.png", png_bytes(w, h, 0, 16, [g * 257 for g in grey]))
    write("image", "rgb8.png", png_bytes(w, h, 2, 8, [(i * 53) % 256 for i in range(3 * w * h)]))
    write("image", "grey_alpha.png", png_bytes(w, h, 4, 8, [(i * 29) % 256 for i in range(2 * w * h)]))
    write("image", "grey.pgm", b"P5 4 3 255\n" + bytes(grey))
    write("image", "rgb.ppm", b"P6 4 3 255\n" + bytes((i * 11) % 256 for i in range(3 * w * h)))
    # A 24-bit BMP: rows bottom up, padded to 4 bytes.
    row = 3 * w + (-(3 * w) % 4)
    pixels = b"".join(bytes((x * 60 + y * 20) % 256 for x in range(3 * w)) + b"\0" * (row - 3 * w)
                      for y in range(h))
    header = struct.pack("<2sIHHI", b"BM", 54 + len(pixels), 0, 0, 54)
    info = struct.pack("<IiiHHIIiiII", 40, w, h, 1, 24, 0, len(pixels), 2835, 2835, 0, 0)
    write("image", "rgb.bmp", header + info + pixels)
    write("image", "grey.jpg", base64.b64decode(JPEG_GREY))
    write("image", "colour_progressive.jpg", base64.b64decode(JPEG_COLOUR))


def main():
    if not os.path.isdir(DATA):
        sys.exit("make_fuzz_seeds.py: %s: no such folder (the shared data)" % DATA)
    nrrd_seeds()
    metaimage_seeds()
    dat_seeds()
    vti_seeds()
    raw_seeds()
    tf_seeds()
    nifti_seeds()
    dicom_seeds()
    tiff_seeds()
    slc_seeds()
    archive_seeds()
    mrc_seeds()
    vtk_seeds()
    image_seeds()


if __name__ == "__main__":
    main()
