#!/usr/bin/python3
"""Writes the small NIfTI, NRRD and DICOM test volumes in this folder from the head CT in
../vtkjs-headsq (see ../README.md, "Derived volumes"). Run from anywhere with Debian's
python3 (python3-numpy, python3-pydicom); the output is committed, so tests need neither.

Every file holds the same 32 x 32 x 24 int16 volume: headsq sampled at every 2nd voxel in x
and y and every 4th slice in z, spacing 6.4 x 6.4 x 6.0 mm, placed in patient space with the
30-degree turn about z that headsq's vtk.js descriptor carries and an origin of
(-100, -80, 20) mm in LPS."""
import gzip
import math
import os
import struct

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.join(HERE, "..", "vtkjs-headsq", "headsq_64x64x93_int16le.raw.gz")

SPACING = (6.4, 6.4, 6.0)
ANGLE = math.radians(30.0)
# Index axes in LPS (columns of the direction matrix): i along (cos, sin, 0), j along
# (-sin, cos, 0), k along +z (superior).
DIRECTIONS_LPS = np.array([[math.cos(ANGLE), -math.sin(ANGLE), 0.0],
                           [math.sin(ANGLE), math.cos(ANGLE), 0.0],
                           [0.0, 0.0, 1.0]])
ORIGIN_LPS = np.array([-100.0, -80.0, 20.0])
LPS_TO_RAS = np.diag([-1.0, -1.0, 1.0])


def volume():
    raw = gzip.open(SOURCE, "rb").read()
    full = np.frombuffer(raw, dtype="<i2").reshape(93, 64, 64)  # z, y, x
    return np.ascontiguousarray(full[::4, ::2, ::2])  # 24 x 32 x 32


def nifti_affine():
    """Index -> RAS affine (4x4) of the volume."""
    a = np.eye(4)
    a[:3, :3] = LPS_TO_RAS @ DIRECTIONS_LPS @ np.diag(SPACING)
    a[:3, 3] = LPS_TO_RAS @ ORIGIN_LPS
    return a


def quaternion(rotation):
    """NIfTI's (b, c, d) of a proper rotation matrix (a >= 0)."""
    r = rotation
    a = 0.5 * math.sqrt(max(0.0, 1.0 + r[0, 0] + r[1, 1] + r[2, 2]))
    return ((r[2, 1] - r[1, 2]) / (4 * a), (r[0, 2] - r[2, 0]) / (4 * a),
            (r[1, 0] - r[0, 1]) / (4 * a))


def write_nifti1(path, data):
    """NIfTI-1, little-endian, qform only (qform_code 1, sform_code 0), gzip."""
    nz, ny, nx = data.shape
    rotation = LPS_TO_RAS @ DIRECTIONS_LPS
    b, c, d = quaternion(rotation)
    offset = LPS_TO_RAS @ ORIGIN_LPS
    h = bytearray(348)
    struct.pack_into("<i", h, 0, 348)
    struct.pack_into("<8h", h, 40, 3, nx, ny, nz, 1, 1, 1, 1)
    struct.pack_into("<hh", h, 70, 4, 16)  # datatype int16, bitpix
    struct.pack_into("<8f", h, 76, 1.0, *SPACING, 0, 0, 0, 0)  # pixdim[0] = qfac = 1
    struct.pack_into("<f", h, 108, 352.0)  # vox_offset
    struct.pack_into("<ff", h, 112, 1.0, 0.0)  # scl_slope, scl_inter
    h[123] = 2  # xyzt_units: millimetres
    struct.pack_into("<hh", h, 252, 1, 0)  # qform_code scanner, sform_code none
    struct.pack_into("<6f", h, 256, b, c, d, *offset)
    text = b"volsg test: headsq 32x32x24"
    h[148:148 + len(text)] = text
    h[344:348] = b"n+1\0"
    body = bytes(h) + b"\0\0\0\0" + data.astype("<i2").tobytes()
    with gzip.GzipFile(path, "wb", mtime=0) as f:
        f.write(body)


def write_nifti2(path, data):
    """NIfTI-2, big-endian, sform only (sform_code 2, qform_code 0), uncompressed, with a
    scl_slope of 0.5: the reader must give FLOAT stored * 0.5 + 10."""
    nz, ny, nx = data.shape
    a = nifti_affine()
    h = bytearray(540)
    struct.pack_into(">i", h, 0, 540)
    h[4:12] = b"n+2\0\r\n\x1a\n"
    struct.pack_into(">hh", h, 12, 4, 16)
    struct.pack_into(">8q", h, 16, 3, nx, ny, nz, 1, 1, 1, 1)
    struct.pack_into(">8d", h, 104, 1.0, *SPACING, 0, 0, 0, 0)
    struct.pack_into(">q", h, 168, 544)
    struct.pack_into(">dd", h, 176, 0.5, 10.0)
    struct.pack_into(">ii", h, 344, 0, 2)
    for r in range(3):
        struct.pack_into(">4d", h, 400 + 32 * r, *a[r])
    struct.pack_into(">i", h, 500, 2)
    body = bytes(h) + b"\0\0\0\0" + data.astype(">i2").tobytes()
    with gzip.GzipFile(path, "wb", mtime=0) as f:
        f.write(body)


def write_dicom(folder, data):
    """A CT series, one file per slice, named in reverse order (the reader must sort by
    position). Stored unsigned 12-bit with Rescale Intercept -1024: the reader gives SHORT
    values stored - 1024."""
    import pydicom
    from pydicom.dataset import Dataset, FileMetaDataset
    from pydicom.uid import ExplicitVRLittleEndian, generate_uid

    os.makedirs(folder, exist_ok=True)
    for name in os.listdir(folder):
        os.remove(os.path.join(folder, name))
    nz, ny, nx = data.shape
    # Fixed UIDs (under pydicom's root) so that running the script again gives the same bytes.
    series = generate_uid(entropy_srcs=["volsg headsq series"])
    study = generate_uid(entropy_srcs=["volsg headsq study"])
    frame = generate_uid(entropy_srcs=["volsg headsq frame"])
    row, col, normal = DIRECTIONS_LPS[:, 0], DIRECTIONS_LPS[:, 1], DIRECTIONS_LPS[:, 2]
    for k in range(nz):
        sop = generate_uid(entropy_srcs=["volsg headsq slice", str(k)])
        meta = FileMetaDataset()
        meta.MediaStorageSOPClassUID = "1.2.840.10008.5.1.4.1.1.2"  # CT Image Storage
        meta.MediaStorageSOPInstanceUID = sop
        meta.TransferSyntaxUID = ExplicitVRLittleEndian
        ds = Dataset()
        ds.file_meta = meta
        ds.is_little_endian = True
        ds.is_implicit_VR = False
        ds.SOPClassUID = meta.MediaStorageSOPClassUID
        ds.SOPInstanceUID = sop
        ds.StudyInstanceUID = study
        ds.SeriesInstanceUID = series
        ds.FrameOfReferenceUID = frame
        ds.Modality = "CT"
        ds.PatientName = "volsg^headsq"
        ds.PatientID = "volsg-headsq"
        ds.InstanceNumber = k + 1
        position = ORIGIN_LPS + normal * SPACING[2] * k
        ds.ImagePositionPatient = [f"{v:.4f}" for v in position]
        ds.ImageOrientationPatient = [f"{v:.6f}" for v in list(row) + list(col)]
        ds.PixelSpacing = [f"{SPACING[1]}", f"{SPACING[0]}"]  # between rows, between columns
        ds.SliceThickness = f"{SPACING[2]}"
        ds.SamplesPerPixel = 1
        ds.PhotometricInterpretation = "MONOCHROME2"
        ds.Rows, ds.Columns = ny, nx
        ds.BitsAllocated, ds.BitsStored, ds.HighBit = 16, 12, 11
        ds.PixelRepresentation = 0
        ds.RescaleIntercept = "-1024"
        ds.RescaleSlope = "1"
        ds.PixelData = data[k].astype("<u2").tobytes()
        name = os.path.join(folder, f"slice-{nz - k:03d}.dcm")
        pydicom.dcmwrite(name, ds, write_like_original=False)


def write_nrrd(path):
    """A detached NRRD header for the chest CT's gzip raw, in RAS with its spacing."""
    with open(path, "w") as f:
        f.write("NRRD0004\n# volsg test: LIDC2 chest CT through a detached header\n"
                "type: uint8\ndimension: 3\nspace: right-anterior-superior\n"
                "sizes: 256 256 133\n"
                "space directions: (1.40625,0,0) (0,1.40625,0) (0,0,2.5)\n"
                "space origin: (0,0,0)\nencoding: gzip\n"
                "data file: lidc2_256x256x133_uint8.raw.gz\n")


def main():
    data = volume()
    write_nifti1(os.path.join(HERE, "headsq_32x32x24_int16.nii.gz"), data)
    write_nifti2(os.path.join(HERE, "headsq_32x32x24_nifti2_be_scaled.nii.gz"), data)
    write_dicom(os.path.join(HERE, "headsq_dicom"), data)
    # Beside its data: a data file names files only inside its own folder.
    write_nrrd(os.path.join(HERE, "..", "vtkjs-lidc2", "lidc2_chest.nhdr"))


if __name__ == "__main__":
    main()
