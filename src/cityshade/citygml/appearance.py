"""CityGML appearances: themes, X3DMaterial, ParameterizedTexture, GeoreferencedTexture.

Appearances are defined apart from the geometry and attach to surfaces through ``#id`` targets,
often at the end of the file, so the reader only records them here; the scene assembly resolves
them against polygons and rings once the whole file is read (:func:`resolve_appearance`).
Both the CityGML 1.0/2.0 encoding (``target uri=`` + ``textureCoordinates ring=``) and the 3.0
encoding (``TextureAssociation`` + ``textureCoordinates``/``ring`` pairs) are read.
"""
from __future__ import annotations

import re
from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

_URL = re.compile(r"^[A-Za-z][A-Za-z0-9+.-]*://")
#: World-file suffixes by image suffix (ESRI convention: first and last letter + "w").
_WORLD_SUFFIXES = (".tfw", ".pgw", ".jgw", ".wld", ".tifw", ".pngw", ".jpgw")


#: X3DMaterial properties, in any namespace (``{*}``: lxml matches the local name in C).
_MATERIAL_PROPERTY_TAGS = tuple("{*}" + name for name in (
    "diffuseColor", "specularColor", "emissiveColor", "ambientIntensity", "shininess",
    "transparency"))


def _local(tag) -> str:
    return tag[tag.rfind("}") + 1:] if isinstance(tag, str) else ""


def _floats(text: str | None) -> list[float]:
    try:
        return [float(v) for v in (text or "").split()]
    except ValueError:
        return []


def _target_id(el) -> str | None:
    """The id a ``target`` points at: its ``uri`` attribute, else its xlink, else its text."""
    # Counting the attributes makes no strings; CityGML 2.0 material targets (often one per
    # polygon of the file) have none, so the two look-ups are skipped for them.
    value = None
    if len(el.attrib):
        value = el.get("uri") or el.get("{http://www.w3.org/1999/xlink}href")
    value = value or (el.text or "").strip()
    if not value:
        return None
    return value[1:] if value.startswith("#") else value


@dataclass
class MaterialRecord:
    theme: str
    diffuse: tuple[float, float, float] = (0.8, 0.8, 0.8)
    ambient_intensity: float = 0.2
    specular: tuple[float, float, float] = (1.0, 1.0, 1.0)
    emissive: tuple[float, float, float] = (0.0, 0.0, 0.0)
    shininess: float = 0.2
    transparency: float = 0.0
    targets: list[str] = field(default_factory=list)

    def to_json(self) -> dict:
        return {"theme": self.theme, "diffuse": list(self.diffuse),
                "ambient_intensity": self.ambient_intensity, "specular": list(self.specular),
                "emissive": list(self.emissive), "shininess": self.shininess,
                "transparency": self.transparency}


@dataclass
class TextureRecord:
    theme: str
    kind: str  # "parameterized" | "georeferenced"
    image_uri: str
    wrap_mode: str = "none"
    border_color: tuple[float, ...] = ()
    #: parameterized: (target polygon/aggregate id, [(ring id, uv text)], worldToTexture or None)
    targets: list[tuple[str, list[tuple[str, str]], list[float] | None]] = field(default_factory=list)
    #: georeferenced: reference point (x, y) of the upper-left pixel centre and 2×2 orientation.
    reference_point: tuple[float, float] | None = None
    orientation: tuple[float, float, float, float] | None = None


class AppearanceCollector:
    """Appearance records of one file, in document order."""

    def __init__(self) -> None:
        self.materials: list[MaterialRecord] = []
        self.textures: list[TextureRecord] = []
        self.theme_targets: Counter = Counter()
        self.counters: Counter = Counter()

    # -- reading ----------------------------------------------------------------------------
    def read_appearance(self, el, walker, owner: int) -> None:
        """Read an ``Appearance`` element or a property that wraps one."""
        if _local(el.tag) != "Appearance":
            for child in el:
                if _local(child.tag) == "Appearance":
                    self.read_appearance(child, walker, owner)
            return
        theme = ""
        for child in el:
            if _local(child.tag) == "theme":
                theme = (child.text or "").strip()
        for child in el:
            if _local(child.tag) not in ("surfaceDataMember", "surfaceData"):
                continue
            if child.get("{http://www.w3.org/1999/xlink}href") is not None:
                self.counters["surface_data_references_ignored"] += 1
            for data in child:
                kind = _local(data.tag)
                if kind == "X3DMaterial":
                    self._material(data, theme)
                elif kind == "ParameterizedTexture":
                    self._parameterized(data, theme)
                elif kind == "GeoreferencedTexture":
                    self._georeferenced(data, theme)

    def _material(self, el, theme: str) -> None:
        # Materials often list a target per polygon of the file (hundreds of thousands): lxml
        # picks the property and target children by local name in C, so no tag string is made
        # per target. Document order is kept within each of the two passes, which is all that
        # matters (properties overwrite one another in order, targets append in order).
        rec = MaterialRecord(theme=theme)
        for child in el.iterchildren(*_MATERIAL_PROPERTY_TAGS):
            name = _local(child.tag)
            values = _floats(child.text)
            if name == "diffuseColor" and len(values) == 3:
                rec.diffuse = tuple(values)
            elif name == "specularColor" and len(values) == 3:
                rec.specular = tuple(values)
            elif name == "emissiveColor" and len(values) == 3:
                rec.emissive = tuple(values)
            elif name == "ambientIntensity" and len(values) == 1:
                rec.ambient_intensity = values[0]
            elif name == "shininess" and len(values) == 1:
                rec.shininess = values[0]
            elif name == "transparency" and len(values) == 1:
                rec.transparency = values[0]
        targets = rec.targets
        for child in el.iterchildren("{*}target"):
            target = _target_id(child)
            if target:
                targets.append(target)
        self.materials.append(rec)
        self.theme_targets[theme] += len(targets)

    def _common_texture(self, el, rec: TextureRecord) -> None:
        for child in el:
            name = _local(child.tag)
            if name == "imageURI":
                rec.image_uri = (child.text or "").strip()
            elif name == "wrapMode":
                rec.wrap_mode = (child.text or "none").strip()
            elif name == "borderColor":
                rec.border_color = tuple(_floats(child.text))

    def _parameterized(self, el, theme: str) -> None:
        rec = TextureRecord(theme=theme, kind="parameterized", image_uri="")
        self._common_texture(el, rec)
        for child in el:
            name = _local(child.tag)
            if name == "target":  # CityGML 1.0 / 2.0
                target = _target_id(child)
                if target:
                    rec.targets.append(self._parameterization(target, child))
            elif name == "textureParameterization":  # CityGML 3.0
                for assoc in child:
                    if _local(assoc.tag) != "TextureAssociation":
                        continue
                    target = None
                    for part in assoc:
                        if _local(part.tag) == "target":
                            target = _target_id(part)
                    if target:
                        params = [p for p in assoc if _local(p.tag) == "textureParameterization"]
                        rec.targets.append(self._parameterization(target, *params))
        self.textures.append(rec)
        self.theme_targets[theme] += len(rec.targets)

    @staticmethod
    def _parameterization(target: str, *containers) -> tuple[str, list[tuple[str, str]], list[float] | None]:
        rings: list[tuple[str, str]] = []
        matrix = None
        for container in containers:
            for param in container:
                name = _local(param.tag)
                if name == "TexCoordList":
                    pending_text = None
                    for item in param:
                        item_name = _local(item.tag)
                        if item_name == "textureCoordinates":
                            ring = item.get("ring")
                            if ring:  # 1.0/2.0: the ring is an attribute
                                rings.append((ring.lstrip("#"), item.text or ""))
                            else:  # 3.0: a ring element follows its coordinates
                                pending_text = item.text or ""
                        elif item_name == "ring" and pending_text is not None:
                            rings.append(((item.text or "").strip().lstrip("#"), pending_text))
                            pending_text = None
                elif name == "TexCoordGen":
                    for item in param:
                        if _local(item.tag) == "worldToTexture":
                            values = _floats(item.text)
                            if len(values) == 12:
                                matrix = values
        return target, rings, matrix

    def _georeferenced(self, el, theme: str) -> None:
        rec = TextureRecord(theme=theme, kind="georeferenced", image_uri="")
        self._common_texture(el, rec)
        for child in el:
            name = _local(child.tag)
            if name == "referencePoint":
                values = _floats(" ".join(t for t in child.itertext()))
                if len(values) >= 2:
                    rec.reference_point = (values[0], values[1])
            elif name == "orientation":
                values = _floats(child.text)
                if len(values) == 4:
                    rec.orientation = tuple(values)
            elif name == "target":
                target = _target_id(child)
                if target:
                    rec.targets.append((target, [], None))
        self.textures.append(rec)
        self.theme_targets[theme] += len(rec.targets)

    # -- choosing ---------------------------------------------------------------------------
    def themes(self) -> list[str]:
        return sorted(self.theme_targets)

    def choose_theme(self, requested: str | None) -> str | None:
        """The theme to use: the requested one, else the one with most targets (first on ties)."""
        if requested is not None:
            return requested if requested in self.theme_targets else None
        if not self.theme_targets:
            return None
        best = max(self.theme_targets.values())
        for rec in [*self.materials, *self.textures]:
            if self.theme_targets[rec.theme] == best:
                return rec.theme
        return None


def resolve_image_path(image_uri: str, gml_path: Path) -> tuple[Path | None, str | None]:
    """Resolve a texture's imageURI relative to the GML file; (path, None) or (None, reason).

    Windows backslashes are accepted. URLs and paths that leave the dataset folder (the folder
    of the GML file) are refused: a model must not make cityshade read arbitrary files.
    """
    uri = image_uri.strip().replace("\\", "/")
    if not uri:
        return None, "empty imageURI"
    if _URL.match(uri):
        return None, f"texture {image_uri!r} is a URL; cityshade never fetches from a network"
    base = gml_path.resolve().parent
    candidate = (base / uri).resolve()
    try:
        candidate.relative_to(base)
    except ValueError:
        return None, f"texture {image_uri!r} is outside the dataset folder {base}"
    if not candidate.is_file():
        return None, f"texture {image_uri!r} not found"
    return candidate, None


def read_world_file(image_path: Path) -> tuple[float, ...] | None:
    """Six values (A, D, B, E, C, F) of the world file next to an image, if there is one."""
    stem = image_path.with_suffix("")
    suffix = image_path.suffix.lower()
    candidates = [suffix[:2] + suffix[-1:] + "w"] if len(suffix) >= 3 else []
    candidates += list(_WORLD_SUFFIXES) + [suffix + "w"]
    for cand in candidates:
        world = stem.with_suffix(cand)
        if world.is_file():
            values = _floats(world.read_text(errors="replace"))
            if len(values) == 6:
                return tuple(values)
    return None


def georeferenced_uv(xy: np.ndarray, reference_point, orientation, width_px: int,
                     height_px: int) -> np.ndarray:
    """Texture coordinates of world points for a GeoreferencedTexture.

    The texture's pixel (col, row) centre lies at ``reference_point + orientation @ (col, row)``
    (CityGML §9.5, the world-file convention); u runs left→right, v bottom→top.
    """
    a, b, c, d = orientation
    matrix = np.array([[a, b], [c, d]], dtype=np.float64)
    col_row = np.linalg.solve(matrix, (xy - np.asarray(reference_point)).T).T
    u = (col_row[:, 0] + 0.5) / width_px
    v = 1.0 - (col_row[:, 1] + 0.5) / height_px
    return np.column_stack([u, v])
