"""Count pixels of an X window dump (xwd -root) for tests/paraview_gui.cc.

    /usr/bin/python3 tests/xwd_pixels.py SHOT.xwd [--png OUT.png]
                                         [--colour NAME=R,G,B]...

Prints, one "key value" per line:

  size WIDTH HEIGHT
  saturated FRACTION      pixels of a strong colour (the largest and the
                          smallest of R, G, B more than 80 apart), other
                          than the --colour ones: ParaView's widgets are
                          grey, a part coloured by a field is not
  colour NAME COUNT       pixels within 40 (each of R, G, B) of R,G,B

--png writes the dump as a PNG (to look at when a check fails).

The XWD format: a header of 25 big-endian 32-bit fields (100 bytes), the
window name up to header_size, ncolors colour entries of 12 bytes, then the
pixels, bytes_per_line per row. Only ZPixmap dumps of 24 or 32 bits per
pixel (TrueColor, what Xvfb's 24-bit screen gives) are read.
"""

import struct
import sys
import zlib

import numpy

FIELDS = ("header_size file_version pixmap_format pixmap_depth width height "
          "xoffset byte_order bitmap_unit bitmap_bit_order bitmap_pad "
          "bits_per_pixel bytes_per_line visual_class red_mask green_mask "
          "blue_mask bits_per_rgb colormap_entries ncolors window_width "
          "window_height window_x window_y window_border_width").split()


def read_xwd(path):
    """The pixels of PATH as a (height, width, 3) uint8 array (R, G, B)."""
    with open(path, "rb") as f:
        data = f.read()
    if len(data) < 100:
        sys.exit("xwd_pixels.py: %s is not an XWD file (%d bytes)" % (path, len(data)))
    header = dict(zip(FIELDS, struct.unpack(">25I", data[:100])))
    if header["file_version"] != 7 or header["pixmap_format"] != 2:
        sys.exit("xwd_pixels.py: %s: not a version 7 ZPixmap dump" % path)
    bpp = header["bits_per_pixel"]
    if bpp not in (24, 32):
        sys.exit("xwd_pixels.py: %s: %d bits per pixel, not read" % (path, bpp))
    width, height, stride = header["width"], header["height"], header["bytes_per_line"]
    start = header["header_size"] + 12 * header["ncolors"]
    end = start + stride * height
    if len(data) < end:
        sys.exit("xwd_pixels.py: %s is cut short" % path)
    rows = numpy.frombuffer(data[start:end], dtype=numpy.uint8).reshape(height, stride)
    nbytes = bpp // 8
    raw = rows[:, :width * nbytes].reshape(height, width, nbytes).astype(numpy.uint32)
    # The pixel as one integer, in the dump's byte order.
    order = range(nbytes) if header["byte_order"] == 0 else range(nbytes - 1, -1, -1)
    value = numpy.zeros((height, width), dtype=numpy.uint32)
    for shift, byte in enumerate(order):
        value |= raw[:, :, byte] << numpy.uint32(8 * shift)
    channels = []
    for mask in (header["red_mask"], header["green_mask"], header["blue_mask"]):
        low = (mask & -mask).bit_length() - 1
        top = mask >> low
        channels.append(((value >> numpy.uint32(low)) & numpy.uint32(top)) * 255 // max(top, 1))
    return numpy.stack(channels, axis=-1).astype(numpy.uint8)


def write_png(path, rgb):
    """RGB (height, width, 3) uint8 as an 8-bit RGB PNG."""
    height, width, _ = rgb.shape
    raw = b"".join(b"\x00" + rgb[y].tobytes() for y in range(height))

    def chunk(kind, body):
        return (struct.pack(">I", len(body)) + kind + body
                + struct.pack(">I", zlib.crc32(kind + body) & 0xFFFFFFFF))
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n"
                + chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 6)) + chunk(b"IEND", b""))


def main(argv):
    """Parse ARGV, print the counts."""
    if not argv or argv[0] in ("-h", "--help"):
        print(__doc__)
        return 0 if argv else 1
    path, png, colours = argv[0], None, []
    i = 1
    while i < len(argv):
        if argv[i] == "--png" and i + 1 < len(argv):
            png = argv[i + 1]
        elif argv[i] == "--colour" and i + 1 < len(argv):
            name, _, value = argv[i + 1].partition("=")
            colours.append((name, [int(c) for c in value.split(",")]))
        else:
            sys.exit("xwd_pixels.py: unknown argument %s" % argv[i])
        i += 2
    rgb = read_xwd(path)
    if png:
        write_png(png, rgb)
    height, width, _ = rgb.shape
    print("size %d %d" % (width, height))
    channels = rgb.astype(numpy.int16)
    saturated = channels.max(axis=-1) - channels.min(axis=-1) > 80
    counts = []
    for name, colour in colours:
        near = (numpy.abs(channels - numpy.array(colour, dtype=numpy.int16)) <= 40).all(axis=-1)
        saturated &= ~near
        counts.append((name, numpy.count_nonzero(near)))
    print("saturated %.4f" % (numpy.count_nonzero(saturated) / float(width * height)))
    for name, count in counts:
        print("colour %s %d" % (name, count))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
