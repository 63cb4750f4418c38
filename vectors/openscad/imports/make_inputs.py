#!/usr/bin/env python3
"""Write the meshes of the import() cases (OFF, AMF, zipped AMF, 3MF) beside this script.

The files are committed; generate.sh then has OpenSCAD 2021.01 import each of them. Run it
again only to change the cases: `python3 make_inputs.py`.
"""
import os
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))

# A cube [0,10]^3: vertices and outward quads.
CUBE_V = [(x, y, z) for z in (0, 10) for y in (0, 10) for x in (0, 10)]
CUBE_F = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]

# An L-shaped prism: the outline (10,4) first, so that a fan from the first vertex crosses
# the notch (a polygon that has to be triangulated, not fanned naively). Its triangles (AMF,
# 3MF) face inward: OpenSCAD's CGAL union takes a closed surface either way, and so must csgpix.
L_OUT = [(10, 4), (4, 4), (4, 10), (0, 10), (0, 0), (10, 0)]


def l_shape(z0=0.0, z1=5.0):
    n = len(L_OUT)
    v = [(x, y, z0) for x, y in L_OUT] + [(x, y, z1) for x, y in L_OUT]
    # The outline is clockwise seen from +z: the bottom cap as is faces down.
    f = [tuple(range(n)), tuple(range(2 * n - 1, n - 1, -1))]
    for i in range(n):
        j = (i + 1) % n
        f.append((i, n + i, n + j, j))
    return v, f


def tris(faces):
    """Fan each face from its first vertex (the L's caps are given as ears instead)."""
    out = []
    for f in faces:
        for k in range(1, len(f) - 1):
            out.append((f[0], f[k], f[k + 1]))
    return out


def l_tris():
    v, f = l_shape()
    n = len(L_OUT)
    # Caps from vertex 4, (0,0), which sees the whole outline.
    bottom = [(4, 5, 0), (4, 0, 1), (4, 1, 2), (4, 2, 3)]
    top = [(n + a, n + c, n + b) for a, b, c in bottom]
    return v, bottom + top + tris(f[2:])


def write(name, text, mode="w"):
    with open(os.path.join(HERE, name), mode) as fh:
        fh.write(text)


def num(c):
    return ("%.6f" % c).rstrip("0").rstrip(".")


def off(v, f, header="OFF", comment=True):
    lines = [header]
    if comment:
        lines.append("# written by make_inputs.py")
    lines.append("%d %d 0" % (len(v), len(f)))
    lines += [" ".join(num(c) for c in p) for p in v]
    lines += ["%d %s" % (len(x), " ".join(map(str, x))) for x in f]
    return "\n".join(lines) + "\n"


def amf_object(oid, v, volumes):
    s = ['  <object id="%d">' % oid, "    <mesh>", "      <vertices>"]
    for p in v:
        s.append("        <vertex><coordinates><x>%s</x><y>%s</y><z>%s</z></coordinates></vertex>"
                 % tuple(num(c) for c in p))
    s.append("      </vertices>")
    for t in volumes:
        s.append("      <volume>")
        for a, b, c in t:
            s.append("        <triangle><v1>%d</v1><v2>%d</v2><v3>%d</v3></triangle>" % (a, b, c))
        s.append("      </volume>")
    s += ["    </mesh>", "  </object>"]
    return s


def amf(objects, unit="millimeter"):
    s = ['<?xml version="1.0" encoding="UTF-8"?>', '<amf unit="%s">' % unit,
         '  <metadata type="name">csgpix</metadata>']
    for i, (v, vols) in enumerate(objects):
        s += amf_object(i, v, vols)
    s.append("</amf>")
    return "\n".join(s) + "\n"


def moved(v, d):
    return [tuple(p[i] + d[i] for i in range(3)) for p in v]


def model_3mf(objects, items, unit="millimeter", extra=""):
    s = ['<?xml version="1.0" encoding="UTF-8"?>',
         '<model unit="%s" xml:lang="en-US" '
         'xmlns="http://schemas.microsoft.com/3dmanufacturing/core/2015/02">' % unit,
         " <resources>"]
    for oid, (v, t) in objects:
        s.append('  <object id="%d" type="model">' % oid)
        s.append("   <mesh>")
        s.append("    <vertices>")
        s += ['     <vertex x="%s" y="%s" z="%s"/>' % tuple(num(c) for c in p) for p in v]
        s.append("    </vertices>")
        s.append("    <triangles>")
        s += ['     <triangle v1="%d" v2="%d" v3="%d"/>' % x for x in t]
        s += ["    </triangles>", "   </mesh>", "  </object>"]
    s.append(extra)
    s.append(" </resources>")
    s.append(" <build>")
    for oid, tr in items:
        s.append('  <item objectid="%d"%s/>' % (oid, ' transform="%s"' % tr if tr else ""))
    s += [" </build>", "</model>"]
    return "\n".join(s) + "\n"


CONTENT_TYPES = """<?xml version="1.0" encoding="UTF-8"?>
<Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types">
 <Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/>
 <Default Extension="model" ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/>
</Types>
"""

RELS = """<?xml version="1.0" encoding="UTF-8"?>
<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">
 <Relationship Target="/%s" Id="rel0" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/>
</Relationships>
"""


def write_zip(name, entries):
    path = os.path.join(HERE, name)
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as z:
        for entry, text in entries:
            info = zipfile.ZipInfo(entry, date_time=(2021, 1, 31, 0, 0, 0))
            info.compress_type = zipfile.ZIP_DEFLATED
            z.writestr(info, text)


def write_3mf(name, model, model_path="3D/3dmodel.model"):
    write_zip(name, [("[Content_Types].xml", CONTENT_TYPES), ("_rels/.rels", RELS % model_path),
                     (model_path, model)])


def main():
    cube_t = tris(CUBE_F)
    lv, lf = l_shape()
    lv_t, l_t = l_tris()
    # OFF: quads, the L's non-convex hexagon caps, and the header variants CGAL reads.
    write("cube.off", off(CUBE_V, CUBE_F))
    write("lshape.off", off(lv, lf))
    write("cube-coff.off", off(moved(CUBE_V, (1, 2, 3)), CUBE_F, header="COFF"))
    # AMF: one object, two objects (overlapping: OpenSCAD unions them), two volumes of one
    # object sharing the face z = 5, and a zipped L.
    write("cube.amf", amf([(CUBE_V, [cube_t])]))
    write("lshape.amf", amf([(lv_t, [l_t])], unit="inch"))
    two = amf([(CUBE_V, [cube_t]), (moved(CUBE_V, (5, 5, 5)), [cube_t])])
    write("two-objects.amf", two)
    slab_v = [(x, y, z) for z in (0, 5, 10) for y in (0, 10) for x in (0, 10)]
    lower = tris([(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)])
    upper = [tuple(i + 4 for i in t) for t in lower]
    write("two-volumes.amf", amf([(slab_v, [lower, upper])]))
    write_zip("zipped.amf", [("zipped.amf", amf([(lv_t, [l_t])]))])
    # 3MF: a cube; an L whose model is elsewhere than 3D/3dmodel.model (named by _rels/.rels);
    # two objects with transformed build items and a component object (OpenSCAD 2021.01
    # takes every mesh object once, as it is: the items, transforms and components are
    # ignored, so the result is the union of the cube and the L where they are defined).
    write_3mf("cube.3mf", model_3mf([(1, (CUBE_V, cube_t))], [(1, None)]))
    write_3mf("lshape.3mf", model_3mf([(1, (lv_t, l_t))], [(1, None)], unit="inch"),
              model_path="3D/part.model")
    comp = ('  <object id="3" type="model"><components>'
            '<component objectid="1" transform="1 0 0 0 1 0 0 0 1 30 0 0"/></components></object>')
    items = [(1, "1 0 0 0 1 0 0 0 1 20 0 0"), (2, "0 1 0 -1 0 0 0 0 1 0 0 3"), (3, None)]
    shifted = moved(lv_t, (3, 3, 2))
    write_3mf("two-items.3mf", model_3mf([(1, (CUBE_V, cube_t)), (2, (shifted, l_t))], items,
                                         extra=comp))


if __name__ == "__main__":
    main()
