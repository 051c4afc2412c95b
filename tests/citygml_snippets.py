"""Small hand-written CityGML documents for reader tests."""
from __future__ import annotations

import copy

from lxml import etree

CG2 = ('xmlns="http://www.opengis.net/citygml/2.0" xmlns:gml="http://www.opengis.net/gml" '
       'xmlns:bldg="http://www.opengis.net/citygml/building/2.0" '
       'xmlns:app="http://www.opengis.net/citygml/appearance/2.0" '
       'xmlns:luse="http://www.opengis.net/citygml/landuse/2.0" '
       'xmlns:veg="http://www.opengis.net/citygml/vegetation/2.0" '
       'xmlns:xlink="http://www.w3.org/1999/xlink"')


def ring(points, ring_id=None) -> str:
    """A closed gml:LinearRing with a posList."""
    pts = list(points) + [points[0]]
    rid = f' gml:id="{ring_id}"' if ring_id else ""
    text = " ".join(f"{x} {y} {z}" for x, y, z in pts)
    return f'<gml:LinearRing{rid}><gml:posList srsDimension="3">{text}</gml:posList></gml:LinearRing>'


def polygon(points, poly_id=None, holes=(), ring_id=None) -> str:
    pid = f' gml:id="{poly_id}"' if poly_id else ""
    inner = "".join(f"<gml:interior>{ring(h)}</gml:interior>" for h in holes)
    return f"<gml:Polygon{pid}><gml:exterior>{ring(points, ring_id)}</gml:exterior>{inner}</gml:Polygon>"


def box_polygons(x0, y0, z0, dx, dy, dz, prefix="p"):
    """Six outward-oriented faces of an axis-aligned box: list of (class, id, points)."""
    x1, y1, z1 = x0 + dx, y0 + dy, z0 + dz
    return [
        ("GroundSurface", f"{prefix}g", [(x0, y0, z0), (x0, y1, z0), (x1, y1, z0), (x1, y0, z0)]),
        ("RoofSurface", f"{prefix}r", [(x0, y0, z1), (x1, y0, z1), (x1, y1, z1), (x0, y1, z1)]),
        ("WallSurface", f"{prefix}s", [(x0, y0, z0), (x1, y0, z0), (x1, y0, z1), (x0, y0, z1)]),
        ("WallSurface", f"{prefix}e", [(x1, y0, z0), (x1, y1, z0), (x1, y1, z1), (x1, y0, z1)]),
        ("WallSurface", f"{prefix}n", [(x1, y1, z0), (x0, y1, z0), (x0, y1, z1), (x1, y1, z1)]),
        ("WallSurface", f"{prefix}w", [(x0, y1, z0), (x0, y0, z0), (x0, y0, z1), (x0, y1, z1)]),
    ]


def building(bid, faces, solid_refs=True, extra="", srs="EPSG:25832") -> str:
    bounded = "".join(
        f"<bldg:boundedBy><bldg:{cls}><bldg:lod2MultiSurface><gml:MultiSurface>"
        f"<gml:surfaceMember>{polygon(pts, pid)}</gml:surfaceMember>"
        f"</gml:MultiSurface></bldg:lod2MultiSurface></bldg:{cls}></bldg:boundedBy>"
        for cls, pid, pts in faces)
    solid = ""
    if solid_refs:
        members = "".join(f'<gml:surfaceMember xlink:href="#{pid}"/>' for _, pid, _ in faces)
        solid = (f'<bldg:lod2Solid><gml:Solid srsName="{srs}"><gml:exterior><gml:CompositeSurface>'
                 f"{members}</gml:CompositeSurface></gml:exterior></gml:Solid></bldg:lod2Solid>")
    # The solid comes first: its references point forward, as in real exports.
    return f'<bldg:Building gml:id="{bid}">{extra}{solid}{bounded}</bldg:Building>'


def tree(tid, faces, kind="SolitaryVegetationObject", codes=()) -> str:
    """A vegetation object (``veg:SolitaryVegetationObject`` or ``veg:PlantCover``) whose
    LoD2 geometry is the polygons ``faces`` ((class, id, points) as :func:`box_polygons`),
    with the attributes ``codes`` ((name, value): ``veg:class``, ``veg:species``...)."""
    members = "".join(f"<gml:surfaceMember>{polygon(pts, pid)}</gml:surfaceMember>"
                      for _, pid, pts in faces)
    prop = "lod2Geometry" if kind == "SolitaryVegetationObject" else "lod2MultiSurface"
    attrs = "".join(f"<veg:{name}>{value}</veg:{name}>" for name, value in codes)
    return (f'<veg:{kind} gml:id="{tid}">{attrs}<veg:{prop}><gml:MultiSurface>{members}'
            f"</gml:MultiSurface></veg:{prop}></veg:{kind}>")


def city(*members: str, ns: str = CG2, appearance: str = "") -> str:
    body = "".join(f"<cityObjectMember>{m}</cityObjectMember>" for m in members)
    if appearance:
        body += f"<app:appearanceMember>{appearance}</app:appearanceMember>"
    return f'<?xml version="1.0" encoding="UTF-8"?>\n<CityModel {ns}>{body}</CityModel>\n'


def ground(x0, y0, x1, y1, z=0.0, gid="ground") -> str:
    """A flat LandUse square facing up (counter-clockwise seen from above)."""
    pts = [(x0, y0, z), (x1, y0, z), (x1, y1, z), (x0, y1, z)]
    return (f'<luse:LandUse gml:id="{gid}"><luse:lod1MultiSurface><gml:MultiSurface>'
            f"<gml:surfaceMember>{polygon(pts, gid + '_poly')}</gml:surfaceMember>"
            f"</gml:MultiSurface></luse:lod1MultiSurface></luse:LandUse>")


def split_citygml(path, out_dir, n_tiles: int, overlap: int = 0) -> list:
    """Write ``path`` as ``n_tiles`` files of consecutive cityObjectMembers, each tile but the
    first repeating the last ``overlap`` members of the one before (a border duplicate);
    every tile keeps the document's other children (envelope, appearances)."""
    root = etree.parse(str(path)).getroot()
    members = [c for c in root if isinstance(c.tag, str)
               and etree.QName(c).localname == "cityObjectMember"]
    for m in members:
        root.remove(m)
    cut = [round(i * len(members) / n_tiles) for i in range(n_tiles + 1)]
    out = []
    for t in range(n_tiles):
        tile = copy.deepcopy(root)
        for m in members[max(0, cut[t] - (overlap if t else 0)):cut[t + 1]]:
            tile.append(copy.deepcopy(m))
        name = out_dir / f"tile_{t}.gml"
        etree.ElementTree(tile).write(str(name), xml_declaration=True, encoding="UTF-8")
        out.append(name)
    return out


def wall_with_window(at=lambda pts: pts, srs="EPSG:25832") -> str:
    """A 10 m x 3 m wall facing -y (before ``at`` moves its points) with a 1 m x 0.2 m window
    (gml:id WIN, z 1.0-1.2) in a hole of it: building HOUSE, wall WALL, polygons WALLPOLY and
    WINPOLY. ``at(points) -> points`` places them (a shift, a turn)."""
    wall = at([(-5.0, 0.0, 0.0), (5.0, 0.0, 0.0), (5.0, 0.0, 3.0), (-5.0, 0.0, 3.0)])
    hole = at([(-0.5, 0.0, 1.0), (-0.5, 0.0, 1.2), (0.5, 0.0, 1.2), (0.5, 0.0, 1.0)])
    win = at([(-0.5, 0.0, 1.0), (0.5, 0.0, 1.0), (0.5, 0.0, 1.2), (-0.5, 0.0, 1.2)])
    return (
        '<bldg:Building gml:id="HOUSE"><bldg:boundedBy><bldg:WallSurface gml:id="WALL">'
        f'<bldg:lod3MultiSurface><gml:MultiSurface srsName="{srs}"><gml:surfaceMember>'
        f"{polygon(wall, 'WALLPOLY', holes=[hole])}</gml:surfaceMember></gml:MultiSurface>"
        "</bldg:lod3MultiSurface><bldg:opening><bldg:Window gml:id=\"WIN\">"
        f"<bldg:lod3MultiSurface><gml:MultiSurface><gml:surfaceMember>{polygon(win, 'WINPOLY')}"
        "</gml:surfaceMember></gml:MultiSurface></bldg:lod3MultiSurface></bldg:Window>"
        "</bldg:opening></bldg:WallSurface></bldg:boundedBy></bldg:Building>")
