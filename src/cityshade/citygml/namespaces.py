"""Namespaces, element names and the tables that classify them.

CityGML comes in 1.0, 2.0, 3.0, the pre-standard ``http://www.citygml.org/citygml/1/0/0``, the
"base profile" namespaces, and files whose ``CityModel`` has no namespace at all. The reader
therefore classifies elements by *local name* and uses the namespace only to tell CityGML and
GML content (read) from ADE content (skipped).
"""
from __future__ import annotations

# The code attribute names, defined with the settings that name them (the reader's ns.*).
from cityshade.config import VEGETATION_CODE_NAMES  # noqa: F401

GML_NAMESPACES = ("http://www.opengis.net/gml", "http://www.opengis.net/gml/3.2")
XLINK_HREF = "{http://www.w3.org/1999/xlink}href"
GML_ID_ATTRS = tuple("{%s}id" % ns for ns in GML_NAMESPACES)

#: Namespace prefixes of CityGML modules (every version, the base profiles and the pre-standard
#: 1/0/0 namespace). Anything else that is not GML is an ADE and is skipped.
CITYGML_NS_PREFIXES = (
    "http://www.opengis.net/citygml/",
    "http://www.citygml.org/citygml/1/0/0",
    "http://www.citygml.org/citygml/profiles/",
)

#: Modules whose elements carry no geometry we render (skipped with their whole subtree).
SKIPPED_CITYGML_MODULES = ("/versioning/", "/dynamizer/", "/pointcloud/")


def citygml_version(namespace: str) -> str | None:
    """CityGML version ("1.0", "2.0", "3.0") from a module namespace, None if not CityGML."""
    if namespace.startswith("http://www.citygml.org/citygml/1/0/0"):
        return "1.0"
    if not namespace.startswith(CITYGML_NS_PREFIXES):
        return None
    for version in ("3.0", "2.0", "1.0"):
        if namespace.endswith("/" + version):
            return version
    return None


#: City object types: elements that become an object of the scene (own gml:id, parent, time).
CITY_OBJECT_TYPES = frozenset("""
    Building BuildingPart BuildingInstallation IntBuildingInstallation BuildingFurniture Room
    BuildingRoom BuildingConstructiveElement Storey BuildingUnit
    Bridge BridgePart BridgeInstallation IntBridgeInstallation BridgeConstructionElement
    BridgeConstructiveElement BridgeRoom BridgeFurniture
    Tunnel TunnelPart TunnelInstallation IntTunnelInstallation HollowSpace TunnelFurniture
    TunnelConstructiveElement
    ReliefFeature TINRelief MassPointRelief BreaklineRelief RasterRelief
    Road Railway Track Square Waterway TransportationComplex Section Intersection TrafficSpace
    AuxiliaryTrafficSpace ClearanceSpace
    WaterBody PlantCover SolitaryVegetationObject CityFurniture LandUse
    GenericCityObject GenericOccupiedSpace GenericUnoccupiedSpace GenericLogicalSpace
    CityObjectGroup OtherConstruction
""".split())

#: Surface classes stored per triangle (uint8). Index = code. Keep the order: it is in the cache.
SURFACE_CLASSES = (
    "unclassified", "roof", "wall", "ground", "closure", "outer_ceiling", "outer_floor",
    "floor", "interior_wall", "ceiling", "door", "window", "terrain", "traffic",
    "auxiliary_traffic", "water", "vegetation", "furniture", "landuse", "generic",
    "installation", "marking",
)
SURFACE_CODE = {name: code for code, name in enumerate(SURFACE_CLASSES)}

#: Thematic surface elements (not objects of their own) → surface class.
THEMATIC_SURFACES = {
    "RoofSurface": "roof", "WallSurface": "wall", "GroundSurface": "ground",
    "ClosureSurface": "closure", "OuterCeilingSurface": "outer_ceiling",
    "OuterFloorSurface": "outer_floor", "FloorSurface": "floor",
    "InteriorWallSurface": "interior_wall", "CeilingSurface": "ceiling",
    "Door": "door", "Window": "window", "TrafficArea": "traffic",
    # CityGML 3.0 filling surfaces (con:fillingSurface of a wall): the 2.0 openings' surfaces.
    "DoorSurface": "door", "WindowSurface": "window",
    "AuxiliaryTrafficArea": "auxiliary_traffic", "Marking": "marking",
    "WaterSurface": "water", "WaterGroundSurface": "water", "WaterClosureSurface": "closure",
    "GenericThematicSurface": "generic", "HoleSurface": "closure",
}

#: Default class of geometry that no thematic surface wraps, by object type.
OBJECT_DEFAULT_CLASS = {
    "ReliefFeature": "terrain", "TINRelief": "terrain", "MassPointRelief": "terrain",
    "BreaklineRelief": "terrain", "RasterRelief": "terrain",
    "Road": "traffic", "Railway": "traffic", "Track": "traffic", "Square": "traffic",
    "Waterway": "traffic", "TransportationComplex": "traffic", "Section": "traffic",
    "Intersection": "traffic", "TrafficSpace": "traffic", "AuxiliaryTrafficSpace": "auxiliary_traffic",
    "WaterBody": "water", "PlantCover": "vegetation", "SolitaryVegetationObject": "vegetation",
    "CityFurniture": "furniture", "LandUse": "landuse", "GenericCityObject": "generic",
    "GenericOccupiedSpace": "generic", "GenericUnoccupiedSpace": "generic",
    "BuildingInstallation": "installation", "BridgeInstallation": "installation",
    "TunnelInstallation": "installation",
}

#: Surface geometry elements: one polygon each (with rings), read by the polygon fast path.
POLYGON_ELEMENTS = frozenset({"Polygon", "Triangle", "PolygonPatch", "Rectangle"})

#: GML elements that only group other geometry: descend into them.
AGGREGATE_ELEMENTS = frozenset("""
    MultiSurface CompositeSurface Surface TriangulatedSurface Tin Shell Solid CompositeSolid
    MultiSolid MultiGeometry GeometricComplex surfaceMember surfaceMembers solidMember
    solidMembers geometryMember geometryMembers patches trianglePatches exterior baseSurface
    element
""".split())

#: GML elements never holding surfaces we draw: curves, points, envelopes.
SKIPPED_GML = frozenset("""
    boundedBy Envelope LineString MultiCurve CompositeCurve Curve MultiPoint Point OrientableCurve
    name description descriptionReference identifier
""".split())

#: CityGML properties never holding geometry we draw: skipped without descending.
SKIPPED_CITYGML = frozenset("""
    externalReference address xalAddress generalizesTo relativeToTerrain relativeToWater
    lod0TerrainIntersection lod1TerrainIntersection lod2TerrainIntersection
    lod3TerrainIntersection lod4TerrainIntersection lod2MultiCurve lod3MultiCurve lod4MultiCurve
    lod0MultiCurve lod1MultiCurve lod0Network lod1Network lod2Network lod3Network lod0BaseLine
    lod1BaseLine lod2BaseLine lod3BaseLine lod1ImplicitRepresentation lod2ImplicitRepresentation
    lod3ImplicitRepresentation lod4ImplicitRepresentation lod0ImplicitRepresentation
    extent breaklines ridgeOrValleyLines reliefPoints controlPoint
    stringAttribute intAttribute doubleAttribute dateAttribute uriAttribute measureAttribute
    genericAttributeSet genericAttribute relatedTo relatedTo3D
    relatedCityObjects groupMember parent
""".split())

#: Implicit geometries: prototypes placed by matrix and reference point (citygml/implicit.py).
IMPLICIT_PROPERTIES = frozenset(f"lod{n}ImplicitRepresentation" for n in range(5))

#: Attributes that give an object's validity interval (docs/DESIGN.md §1).
#: Object types whose ``class``, ``function``, ``usage`` and ``species`` codes are kept
#: (:attr:`cityshade.citygml.reader.RawModel.obj_codes`: which crowns are evergreen,
#: docs/DESIGN.md §21), and those attribute names (CityGML 1.0-3.0 ``veg:`` elements,
#: CityJSON attributes).
VEGETATION_CODE_TYPES = frozenset({"SolitaryVegetationObject", "PlantCover"})

TIME_ATTRIBUTES = frozenset({
    "validFrom", "validTo", "yearOfConstruction", "yearOfDemolition", "dateOfConstruction",
    "dateOfDemolition", "creationDate", "terminationDate",
})
