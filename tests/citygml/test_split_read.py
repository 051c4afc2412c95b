"""The two-process read of a large CityGML file (cityshade.citygml.split) gives the model of
one read, field for field: on every real file cut at several places, on a file made to have
every kind of record cross the cut, through the real child process, and with the fallbacks."""
from __future__ import annotations

import os
import re
import threading
from pathlib import Path

import numpy as np
import pytest

from citygml_snippets import box_polygons, building, polygon
from conftest import SHARED_DATA

from cityshade.citygml import split
from cityshade.citygml.implicit import place_instances
from cityshade.citygml.reader import RawModel, _root_of, read_citygml
from cityshade.errors import CityshadeError, XMLSyntaxError

SAMPLE = Path(__file__).resolve().parents[2] / "sample_data" / "sample_city.gml"


def assert_same_model(a: RawModel, b: RawModel, where: str = "") -> None:
    """Every field equal: arrays by dtype, shape and value, dicts and lists in order."""
    for name in vars(a):
        x, y = getattr(a, name), getattr(b, name)
        if isinstance(x, np.ndarray):
            assert x.dtype == y.dtype and x.shape == y.shape, (where, name)
            assert np.array_equal(x, y, equal_nan=x.dtype.kind == "f"), (where, name)
        elif name == "appearance":
            assert x.materials == y.materials and x.textures == y.textures, (where, name)
            assert list(x.theme_targets.items()) == list(y.theme_targets.items()), where
            assert x.counters == y.counters, where
        elif isinstance(x, dict):
            assert list(x.items()) == list(y.items()), (where, name)
        else:
            assert x == y, (where, name)


def two_part_model(path: Path, plan: split.Plan) -> RawModel | None:
    """The merged model of the two parts, read in this process (None where the first part
    does not close at the root, i.e. the cut was not between top-level members)."""
    root_ns, _ = _root_of(path, recover=False)
    try:
        head = split.read_head(path, plan, root_ns, None, frozenset())
    except CityshadeError:
        return None
    tail = split.read_tail(path, plan, root_ns, None, frozenset())
    split.merge(head, tail)
    place_instances(head)  # as read_citygml does after the parts are merged
    return head


def citygml_files() -> list[Path]:
    if not SHARED_DATA.is_dir():
        return []
    return sorted(p for p in SHARED_DATA.rglob("*") if p.suffix.lower() in (".gml", ".xml")
                  and p.is_file())


def test_every_real_file_cut_anywhere_reads_as_one(shared_data):
    """Each real CityGML file that reads cleanly, cut before the member nearest a fifth, half
    and four fifths of it: the merged model equals the one of one read."""
    cut_files = cuts = 0
    for path in citygml_files():
        try:
            whole = read_citygml(path)
        except CityshadeError:
            continue  # the invalid-file tests' business; a split read falls back there
        size = path.stat().st_size
        seen = set()
        for share in (0.2, 0.5, 0.8):
            plan = split.find_cut(path, size, share)
            if plan is None or plan.cut in seen:
                continue
            seen.add(plan.cut)
            merged = two_part_model(path, plan)
            if merged is None:
                continue
            assert_same_model(whole, merged, f"{path.name} cut at {plan.cut}")
            cuts += 1
        cut_files += bool(seen)
    assert cut_files >= 20 and cuts >= 40, (cut_files, cuts)


PRETTY_PROLOG = ('<?xml version="1.0" encoding="UTF-8"?>\n<!-- made for the split test -->\n'
                 '<!DOCTYPE CityModel>\n')
NAMESPACES = ('xmlns="http://www.opengis.net/citygml/2.0" xmlns:gml="http://www.opengis.net/gml"'
              '\n  xmlns:bldg="http://www.opengis.net/citygml/building/2.0"\n'
              '  xmlns:app="http://www.opengis.net/citygml/appearance/2.0"\n'
              '  xmlns:ade="http://example.com/ade" xmlns:xlink="http://www.w3.org/1999/xlink"')


def crossing_document(blank_lines: int = 0) -> str:
    """A city whose records cross any cut between its members: a polygon id met again later
    (counted duplicate), xlinks back to an earlier member, an aggregate id and a ring id used
    twice (first wins), building parts (parent indices), a window (openings), ADE elements
    (distinct tags counted once), srsNames, and an appearance member at the end that targets
    polygons and rings of every member. ``blank_lines`` between members put later ones past
    line 65535."""
    faces_a = box_polygons(0, 0, 0, 10, 10, 6, prefix="a")
    faces_b = box_polygons(20, 0, 0, 8, 8, 9, prefix="b")
    window = ('<bldg:opening><bldg:Window gml:id="W1"><bldg:lod3MultiSurface><gml:MultiSurface>'
              f'<gml:surfaceMember>{polygon([(20, 0, 1), (21, 0, 1), (21, 0, 2), (20, 0, 2)], "win")}'
              '</gml:surfaceMember></gml:MultiSurface></bldg:lod3MultiSurface></bldg:Window>'
              '</bldg:opening>')
    part = ('<bldg:consistsOfBuildingPart>\n      <bldg:BuildingPart gml:id="B2p">\n'
            '        <bldg:lod2MultiSurface><gml:MultiSurface gml:id="agg1">'
            f'<gml:surfaceMember>{polygon([(30, 0, 0), (31, 0, 0), (31, 0, 1)], "ag", ring_id="ring1")}'
            '</gml:surfaceMember></gml:MultiSurface></bldg:lod2MultiSurface>\n'
            '      </bldg:BuildingPart>\n    </bldg:consistsOfBuildingPart>')
    refs_back = ('<bldg:lod2MultiSurface><gml:MultiSurface>'
                 '<gml:surfaceMember xlink:href="#ag"/><gml:surfaceMember xlink:href="#ar"/>'
                 '</gml:MultiSurface></bldg:lod2MultiSurface>')
    first_agg = ('<bldg:lod1MultiSurface><gml:MultiSurface gml:id="agg1" srsName="EPSG:25832">'
                 f'<gml:surfaceMember>{polygon([(0, 0, 0), (1, 0, 0), (1, 1, 0)], "ag", ring_id="ring1")}'
                 '</gml:surfaceMember></gml:MultiSurface></bldg:lod1MultiSurface>')
    members = [
        building("B1", faces_a, extra=f"<ade:note>x</ade:note>{first_agg}"),
        building("B2", faces_b, extra=f"<ade:note>y</ade:note><ade:other/>{window}{part}"),
        f'<bldg:Building gml:id="B3">{refs_back}</bldg:Building>',
        building("B4", box_polygons(40, 0, 0, 5, 5, 5, prefix="a")),  # a's ids again
    ]
    appearance = (
        '<app:Appearance><app:theme>paint</app:theme><app:surfaceDataMember><app:X3DMaterial>'
        '<app:diffuseColor>0.9 0.1 0.1</app:diffuseColor>'
        + "".join(f"<app:target>#{pid}</app:target>" for _, pid, _ in faces_a + faces_b)
        + '</app:X3DMaterial></app:surfaceDataMember><app:surfaceDataMember>'
        '<app:ParameterizedTexture><app:imageURI>tex/none.png</app:imageURI>'
        '<app:target uri="#ag"><app:TexCoordList><app:textureCoordinates ring="#ring1">'
        '0 0 1 0 1 1 0 0</app:textureCoordinates></app:TexCoordList></app:target>'
        '</app:ParameterizedTexture></app:surfaceDataMember></app:Appearance>')
    gap = "\n" * blank_lines
    body = "".join(f"  <cityObjectMember>\n    {m}\n  </cityObjectMember>\n{gap}"
                   for m in members)
    body += f"  <app:appearanceMember>\n    {appearance}\n  </app:appearanceMember>\n"
    return (f"{PRETTY_PROLOG}<CityModel {NAMESPACES}>\n  <gml:boundedBy><gml:Envelope "
            f'srsName="EPSG:25832"/></gml:boundedBy>\n{body}</CityModel>\n')


def member_starts(text: bytes) -> list[int]:
    return [m.start() for m in split._MEMBER_START.finditer(text)]


def test_every_record_crossing_every_cut_reads_as_one(tmp_path):
    path = tmp_path / "crossing.gml"
    path.write_text(crossing_document())
    data = path.read_bytes()
    whole = read_citygml(path)
    assert whole.counters["duplicate_gml_ids"] >= 7 and whole.counters["ade_elements_skipped"] == 2
    assert whole.openings and "agg1" in whole.aggregates and 1 in whole.obj_parent
    root_end, qname = split._root_start_tag(data[:65536])
    starts = member_starts(data)
    assert len(starts) == 5
    for cut in starts[1:]:
        merged = two_part_model(path, split.Plan(root_end, qname, cut))
        assert merged is not None, cut
        assert_same_model(whole, merged, f"cut at {cut}")


def test_lines_past_65535_are_the_start_tags_lines(tmp_path):
    """libxml2 2.14 names an element from line 65535 on by the end of its first text child;
    the reader corrects that where the text follows the start tag (a pretty-printed object,
    or one whose first children lead to text), so those objects get the line of their start
    tag (found here by searching the text, not by lxml). B3 and B4 start with empty xlink
    members and keep libxml2's answer. Two parts give the lines of one read in every case."""
    path = tmp_path / "long.gml"
    text = crossing_document(blank_lines=70_000).replace(
        '<bldg:Building gml:id="B4">', '<bldg:Building gml:id="B4">\n      ')
    path.write_text(text)
    lines = {m.group(1): text.count("\n", 0, m.start()) + 1
             for m in re.finditer(r'<bldg:Building(?:Part)? gml:id="([^"]+)"', text)}
    assert min(lines[k] for k in ("B2", "B2p", "B3", "B4")) > 65535
    whole = read_citygml(path)
    got = dict(zip(whole.obj_ids, whole.obj_line))
    assert {k: got[k] for k in ("B1", "B2", "B2p", "B4")} == {
        k: lines[k] for k in ("B1", "B2", "B2p", "B4")}
    data = path.read_bytes()
    root_end, qname = split._root_start_tag(data[:65536])
    for cut in member_starts(data)[1:]:
        merged = two_part_model(path, split.Plan(root_end, qname, cut))
        assert merged.obj_line == whole.obj_line, cut


def force_split(monkeypatch, share: float) -> None:
    monkeypatch.setattr(split, "MIN_SPLIT_BYTES", 0)
    monkeypatch.setattr(split, "SPLIT_AT", share)
    monkeypatch.delenv("CITYSHADE_READ_SPLIT", raising=False)


def test_the_child_process_reads_the_tail(tmp_path, monkeypatch):
    """Through the real child: the sample city and the crossing file read as one, the progress
    rises to the file's size, and the first part is this process's."""
    for path, share in ((SAMPLE, 0.5), (tmp_path / "crossing.gml", 0.6)):
        if not path.exists():
            path.write_text(crossing_document())
        whole = read_citygml(path)
        force_split(monkeypatch, share)
        calls = []
        real = split.read_split
        monkeypatch.setattr(split, "read_split", lambda *a: calls.append(1) or real(*a))
        seen = []
        two = read_citygml(path, progress=lambda done, total: seen.append((done, total)))
        monkeypatch.undo()
        assert calls == [1]
        assert_same_model(whole, two, path.name)
        size = path.stat().st_size
        assert seen[-1] == (size, size) and [d for d, _ in seen] == sorted(d for d, _ in seen)


def test_a_failing_child_or_a_bad_cut_reads_in_one_pass(tmp_path, monkeypatch):
    """A child that fails, and a cut inside a member (the first part's end tag then closes an
    inner element), give the one-read model; a malformed tail gives one read's error."""
    path = tmp_path / "crossing.gml"
    path.write_text(crossing_document())
    whole = read_citygml(path)
    force_split(monkeypatch, 0.5)
    monkeypatch.setattr(split.sys, "executable", "/bin/false")
    assert split.read_split(path, split.plan(path, path.stat().st_size), "", None,
                            frozenset()) is None
    assert_same_model(whole, read_citygml(path), "failed child")
    monkeypatch.undo()
    data = path.read_bytes()
    root_end, qname = split._root_start_tag(data[:65536])
    inside = data.index(b"<bldg:boundedBy>", member_starts(data)[1])
    bad = split.Plan(root_end, qname, inside)
    root_ns, _ = _root_of(path, recover=False)
    assert split.read_split(path, bad, root_ns, None, frozenset()) is None
    broken = tmp_path / "broken.gml"
    last = data.rindex(b"</bldg:Building>")  # in the tail of every cut
    broken.write_bytes(data[:last] + b"</bldg:Buildin>" + data[last + 16:])
    with pytest.raises(XMLSyntaxError) as one:
        read_citygml(broken)
    force_split(monkeypatch, 0.5)
    with pytest.raises(XMLSyntaxError) as two:
        read_citygml(broken)
    assert (one.value.message, one.value.line) == (two.value.message, two.value.line)


def test_ctrl_c_during_the_first_part_stops_the_child(tmp_path, monkeypatch):
    path = tmp_path / "crossing.gml"
    path.write_text(crossing_document())
    force_split(monkeypatch, 0.6)
    children = []
    real_child = split._Child
    monkeypatch.setattr(split, "_Child", lambda *a: children.append(real_child(*a)) or children[-1])

    def interrupt(done, total):
        raise KeyboardInterrupt

    with pytest.raises(KeyboardInterrupt):
        read_citygml(path, progress=interrupt)
    assert len(children) == 1 and children[0].proc.returncode is not None
    assert not any(t.name == "cityshade-ring-parse" for t in threading.enumerate())


@pytest.mark.parametrize("prolog, expected", [
    (b'<?xml version="1.0" encoding="UTF-16"?><CityModel>', None),
    (b'\xff\xfe<\x00C\x00', None),
    (b'<!DOCTYPE CityModel [<!ELEMENT CityModel ANY>]><CityModel>', None),
    (b'<CityModel/>', None),
    (b'\xef\xbb\xbf<?xml version="1.0" encoding="iso-8859-1"?>\n<!-- a > b -->\n'
     b'<core:CityModel a="x>y" b=\'1\'>', b"core:CityModel"),
])
def test_prologs_a_byte_cut_can_copy(prolog, expected):
    """The root start tag is found past a BOM, declaration, comment and quoted '>'; other
    encodings, an internal DTD subset and an empty root are not cut."""
    found = split._root_start_tag(prolog + b"<x/>")
    assert found == (None if expected is None else (len(prolog), expected))


def test_small_files_and_one_core_read_in_one_process(tmp_path, monkeypatch):
    path = tmp_path / "crossing.gml"
    path.write_text(crossing_document())
    size = path.stat().st_size
    assert split.plan(path, size) is None  # below MIN_SPLIT_BYTES
    monkeypatch.setattr(split, "MIN_SPLIT_BYTES", 0)
    assert split.plan(path, size) is not None
    monkeypatch.setattr(os, "sched_getaffinity", lambda pid: {0})
    assert split.plan(path, size) is None
    monkeypatch.undo()
    monkeypatch.setattr(split, "MIN_SPLIT_BYTES", 0)
    monkeypatch.setenv("CITYSHADE_READ_SPLIT", "0")
    assert split.plan(path, size) is None
