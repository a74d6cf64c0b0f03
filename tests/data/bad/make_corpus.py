#!/usr/bin/env python3
"""Writes the bad-input corpus (one file per case) and EXPECTED.tsv into this folder.

Each case is the small valid layout BASE with one line changed, so the expected line is exact.
Run it from anywhere: python3 tests/data/bad/make_corpus.py  (deterministic; gzip -n style).
"""
import gzip, io, os, shutil, subprocess

HERE = os.path.dirname(os.path.abspath(__file__))

BASE = [
    '<?xml version="1.0" encoding="UTF-8"?>',                                                  # 1
    '<layout name="bad" version="1">',                                                          # 2
    '  <boundary x0="0" y0="0" x1="10000" y1="10000"/>',                                       # 3
    '  <blockage id="ram0"><rect x0="1000" y0="1000" x1="2000" y1="2000"/></blockage>',       # 4
    '  <net name="n0">',                                                                        # 5
    '    <pin name="p0" x="100" y="100"/>',                                                     # 6
    '    <pin name="p1" x="9000" y="9000"/>',                                                   # 7
    '  </net>',                                                                                 # 8
    '</layout>',                                                                                # 9
]

rows = []  # file, code, line, object, lenient_ok, severity


def text(changes=None, inserts=None):
    """BASE with line k (1-based) replaced by changes[k]; inserts[k] goes before line k."""
    lines = list(BASE)
    for k, v in sorted((changes or {}).items()):
        lines[k - 1] = v
    for k, v in sorted((inserts or {}).items(), reverse=True):
        lines[k - 1:k - 1] = v if isinstance(v, list) else [v]
    return '\n'.join(lines) + '\n'


def case(name, body, code, line, obj, lenient='no', severity='error'):
    data = body.encode('utf-8') if isinstance(body, str) else body
    with open(os.path.join(HERE, name), 'wb') as f:
        f.write(data)
    rows.append((name, code, str(line), obj, lenient, severity))


def rect_x1(value):
    return {4: '  <blockage id="ram0"><rect x0="1000" y0="1000" x1="%s" y1="2000"/></blockage>' % value}


def poly(points, holes=()):
    """Blockage "p" with a polygon on line 4 (and holes on the following lines)."""
    if not holes:
        return {4: '  <blockage id="p"><polygon points="%s"/></blockage>' % points}
    lines = ['  <blockage id="p"><polygon points="%s">' % points]
    lines += ['    <hole points="%s"/>' % h for h in holes]
    lines += ['  </polygon></blockage>']
    return lines


# --- XML and security -------------------------------------------------------------------------
DT = '<layout name="&xxe;" version="1">'
case('xxe_file.xml', text({2: DT}, {2: '<!DOCTYPE layout [<!ENTITY xxe SYSTEM "file:///etc/passwd">]>'}),
     'IO-0006', 2, 'DOCTYPE')
case('xxe_http.xml', text({2: DT}, {2: '<!DOCTYPE layout [<!ENTITY xxe SYSTEM "http://127.0.0.1:9/secret">]>'}),
     'IO-0006', 2, 'DOCTYPE')
case('xxe_parameter_entity.xml',
     text(None, {2: '<!DOCTYPE layout [<!ENTITY % ext SYSTEM "file:///etc/passwd"> %ext;]>'}),
     'IO-0006', 2, 'DOCTYPE')
case('external_dtd.xml', text(None, {2: '<!DOCTYPE layout SYSTEM "file:///etc/passwd">'}),
     'IO-0006', 2, 'DOCTYPE')
case('external_dtd_http.xml',
     text(None, {2: '<!DOCTYPE layout PUBLIC "-//taut//layout//EN" "http://127.0.0.1:9/layout.dtd">'}),
     'IO-0006', 2, 'DOCTYPE')
laughs = ['<!DOCTYPE layout [', ' <!ENTITY lol "lol">']
laughs += [' <!ENTITY lol%d "%s">' % (i, ('&lol%s;' % ('' if i == 1 else i - 1)) * 10) for i in range(1, 10)]
laughs += [']>']
case('billion_laughs.xml', text({2: '<layout name="&lol9;" version="1">'}, {2: laughs}), 'IO-0006', 2, 'DOCTYPE')
big = 'a' * 50000
case('quadratic_blowup.xml',
     text({2: '<layout name="%s" version="1">' % ('&big;' * 20000)},
          {2: '<!DOCTYPE layout [<!ENTITY big "%s">]>' % big}),
     'IO-0006', 2, 'DOCTYPE')
case('entity_undeclared.xml', text({2: '<layout name="&foo;" version="1">'}), 'IO-0005', 2, "'foo'")
gz = io.BytesIO()
with gzip.GzipFile(fileobj=gz, mode='wb', mtime=0, filename='') as g:
    g.write(text().encode())
case('gzip.xml.gz', gz.getvalue(), 'IO-0003', 0, 'gzip')
import lzma, bz2
case('xz.xml.xz', lzma.compress(text().encode()), 'IO-0003', 0, 'xz')
case('bzip2.xml.bz2', bz2.compress(text().encode()), 'IO-0003', 0, 'bzip2')
import zlib
case('zlib.xml.zz', zlib.compress(text().encode()), 'IO-0003', 0, 'zlib')
# zstd frame: magic + a minimal raw-block frame (the magic is all the reader looks at).
case('zstd.xml.zst', bytes([0x28, 0xb5, 0x2f, 0xfd, 0x20, 0x00, 0x01, 0x00, 0x00]), 'IO-0003', 0, 'zstd')
case('deep_nesting.xml', text(None, {3: '<a>' * 100000}), 'IO-0005', 3, 'Excessive depth')
full = text()
cut = full.index('y0="1000"')  # mid-attribute on line 4
case('truncated.xml', full[:cut + 4], 'IO-0005', 4, '-')
case('malformed_tag.xml',
     text({4: '  <blockage id="ram0"><rect x0="1000" y0="1000" x1="2000" y1="2000"></blockage>'}),
     'IO-0005', 4, 'mismatch')
case('malformed_attribute.xml',
     text({4: '  <blockage id="ram0"><rect x0=1000 y0="1000" x1="2000" y1="2000"/></blockage>'}),
     'IO-0005', 4, '-')
case('bad_utf8.xml', text({2: '<layout name="b\udcffd" version="1">'}).encode('utf-8', 'surrogateescape'),
     'IO-0005', 2, 'UTF-8')
case('empty.xml', b'', 'IO-0004', 0, 'empty')
case('wrong_root.xml', text({2: '<design name="bad" version="1">', 9: '</design>'}), 'IO-0007', 2, 'design')
case('text_content.xml',
     text({4: '  <blockage id="ram0">oops<rect x0="1000" y0="1000" x1="2000" y1="2000"/></blockage>'}),
     'IO-0011', 4, '"oops"')

# --- elements and attributes ------------------------------------------------------------------
case('unknown_element.xml',
     text({4: '  <blockage id="ram0"><circle r="5"/><rect x0="1000" y0="1000" x1="2000" y1="2000"/></blockage>'}),
     'IO-0008', 4, '<circle>', 'yes')
case('unknown_attribute.xml',
     text({4: '  <blockage id="ram0"><rect x0="1000" y0="1000" x1="2000" y1="2000" layer="m1"/></blockage>'}),
     'IO-0009', 4, 'layer', 'yes')
case('unknown_layout_element.xml', text(None, {9: '  <via x="5" y="5"/>'}), 'IO-0008', 9, '<via>', 'yes')
case('missing_attribute.xml',
     text({4: '  <blockage id="ram0"><rect x0="1000" y0="1000" x1="2000"/></blockage>'}),
     'IO-0010', 4, 'y1')
case('missing_id.xml', text({4: '  <blockage><rect x0="1000" y0="1000" x1="2000" y1="2000"/></blockage>'}),
     'IO-0010', 4, 'id')
case('duplicate_attribute.xml',
     text({4: '  <blockage id="ram0"><rect x0="1000" x0="1000" y0="1000" x1="2000" y1="2000"/></blockage>'}),
     'IO-0005', 4, 'x0')
NUM = 'blockage "ram0" rect: attribute x1'
for name, value, code in [('nan', 'nan', 'IO-0012'), ('inf', 'inf', 'IO-0012'), ('1e3', '1e3', 'IO-0012'),
                          ('0x10', '0x10', 'IO-0012'), ('1.5', '1.5', 'IO-0012'),
                          ('leading_space', ' 12', 'IO-0012'), ('12abc', '12abc', 'IO-0012'),
                          ('plus', '+5', 'IO-0012'), ('empty', '', 'IO-0012'), ('minus_only', '-', 'IO-0012'),
                          ('2p31', '2147483648', 'IO-0013'), ('20_digits', '12345678901234567890', 'IO-0013'),
                          ('2p30', '1073741824', 'IO-0013'), ('minus_2p30', '-1073741824', 'IO-0013')]:
    case('number_%s.xml' % name, text(rect_x1(value)), code, 4, NUM)
case('number_pin_x.xml', text({6: '    <pin name="p0" x="1.5" y="100"/>'}), 'IO-0012', 6,
     'net "n0" pin "p0": attribute x')
case('points_separator.xml', text(poly('1000,1000;2000,1000;2000,2000')), 'IO-0014', 4, 'points')
case('points_space_in_pair.xml', text(poly('1000, 1000 2000,1000 2000,2000')), 'IO-0014', 4, 'points')
case('points_odd.xml', text(poly('1000,1000 2000,1000 2000')), 'IO-0014', 4, 'points')
case('points_float.xml', text(poly('1000,1000 2000.5,1000 2000,2000')), 'IO-0014', 4, '"2000.5"')
case('points_2p30.xml', text(poly('1000,1000 1073741824,1000 2000,2000')), 'IO-0014', 4,
     '"1073741824" is out of range [-1073741823, 1073741823]')
case('orientations_bad.xml', text(None, {4: '  <rules orientations="c:0,-45"/>'}), 'IO-0015', 4, 'orientations')
case('orientations_unknown.xml', text(None, {4: '  <rules orientations="manhattan"/>'}), 'IO-0015', 4,
     'orientations')
case('rules_negative.xml', text(None, {4: '  <rules wire-width="-2"/>'}), 'IO-0013', 4, 'wire-width')
case('boundary_twice.xml', text(None, {4: '  <boundary x0="0" y0="0" x1="5" y1="5"/>'}), 'IO-0016', 4,
     'boundary')
case('pin_point_and_shape.xml',
     text({6: '    <pin name="p0" x="100" y="100"><rect x0="0" y0="0" x1="200" y1="200"/></pin>'}),
     'IO-0017', 6, 'pin "p0"')
case('pin_neither.xml', text({6: '    <pin name="p0"/>'}), 'IO-0017', 6, 'pin "p0"')
case('pin_only_x.xml', text({6: '    <pin name="p0" x="100"/>'}), 'IO-0017', 6, 'pin "p0"')
case('version_2.xml', text({2: '<layout name="bad" version="2">'}), 'IO-0018', 2, 'version')
ROUTES = lambda r: ['  <routes tool="t">', r, '  </routes>']
case('route_bad_status.xml', text(None, {9: ROUTES('    <route net="n0" status="done"/>')}),
     'IO-0019', 10, 'status')
case('route_bad_length.xml', text(None, {9: ROUTES('    <route net="n0" status="failed" length="1.5"/>')}),
     'IO-0019', 10, 'length')
# <routes orientations> and metric are checked as <rules orientations> is (since 2026-12-06: a typo
# made taut check skip the wires' directions without a word)
case('routes_orientations_unknown.xml',
     text(None, {9: ['  <routes tool="t" orientations="rectilniear">', '    <route net="n0" status="failed"/>', '  </routes>']}),
     'IO-0015', 9, 'rectilniear')
case('routes_orientations_one_direction.xml',
     text(None, {9: ['  <routes tool="t" orientations="c:0,180">', '    <route net="n0" status="failed"/>', '  </routes>']}),
     'IO-0015', 9, 'fewer than 2 distinct directions')
case('routes_metric_unknown.xml',
     text(None, {9: ['  <routes tool="t" metric="manhattan">', '    <route net="n0" status="failed"/>', '  </routes>']}),
     'IO-0023', 9, 'manhattan')
case('blockage_empty.xml', text({4: '  <blockage id="ram0"/>'}), 'IO-0020', 4, 'ram0')
case('wire_one_point.xml',
     text(None, {9: ROUTES('    <route net="n0" status="routed"><wire points="100,100"/></route>')}),
     'IO-0021', 10, 'wire')
case('empty_net_name.xml', text({5: '  <net name="">'}), 'IO-0022', 5, 'name')

# --- geometry -----------------------------------------------------------------------------------
case('rect_empty_x.xml', text({4: '  <blockage id="ram0"><rect x0="2000" y0="1000" x1="1000" y1="2000"/></blockage>'}),
     'GEOM-0010', 4, 'blockage "ram0" rect')
case('rect_empty_y.xml', text({4: '  <blockage id="ram0"><rect x0="1000" y0="1000" x1="2000" y1="1000"/></blockage>'}),
     'GEOM-0010', 4, 'blockage "ram0" rect')
case('boundary_empty.xml', text({3: '  <boundary x0="0" y0="0" x1="0" y1="10000"/>'}), 'GEOM-0010', 3, 'boundary')
# Codes of geom::validate_polygon (geom/validate.h); the first problem reported is the one listed.
case('polygon_two_points.xml', text(poly('1000,1000 3000,3000 1000,1000')), 'GEOM-0001', 4, 'blockage "p" polygon')
case('polygon_collinear.xml', text(poly('1000,1000 2000,1000 3000,1000')), 'GEOM-0002', 4, 'blockage "p" polygon')
# Zero area without being collinear: the boundary runs out and back (reported as a spike).
case('polygon_zero_area.xml', text(poly('1000,1000 3000,1000 3000,3000 3000,1000')), 'GEOM-0004', 4,
     'blockage "p" polygon')
case('polygon_bowtie.xml', text(poly('1000,1000 3000,3000 3000,1000 1000,4000')), 'GEOM-0003', 4,
     'blockage "p" polygon')
case('polygon_spike.xml', text(poly('1000,1000 3000,1000 3000,2000 4000,2000 3000,2000 3000,3000 1000,3000')),
     'GEOM-0004', 4, 'blockage "p" polygon')
case('hole_outside_shell.xml',
     text(None, {4: poly('1000,1000 3000,1000 3000,3000 1000,3000', ['5000,5000 6000,5000 6000,6000 5000,6000'])}),
     'GEOM-0005', 5, 'blockage "p" polygon: hole 0')

# --- meaning ------------------------------------------------------------------------------------
case('duplicate_blockage_id.xml',
     text(None, {5: '  <blockage id="ram0"><rect x0="3000" y0="3000" x1="4000" y1="4000"/></blockage>'}),
     'LAYOUT-0001', 5, 'blockage "ram0"')
case('duplicate_net_name.xml',
     text(None, {9: ['  <net name="n0">', '    <pin name="a" x="1" y="1"/>', '    <pin name="b" x="2" y="2"/>',
                     '  </net>']}),
     'LAYOUT-0002', 9, 'net "n0"')
case('duplicate_pin_name.xml', text({7: '    <pin name="p0" x="9000" y="9000"/>'}), 'LAYOUT-0003', 7,
     'net "n0" pin "p0"')
case('pin_in_blockage.xml', text({6: '    <pin name="p0" x="1500" y="1500"/>'}), 'LAYOUT-0004', 6,
     'net "n0" pin "p0" at (1500,1500) lies inside blockage "ram0"')
case('pin_between_touching_blockages.xml',
     text({6: '    <pin name="p0" x="2000" y="1500"/>'},
          {5: '  <blockage id="next"><rect x0="2000" y0="1000" x1="3000" y1="2000"/></blockage>'}),
     'LAYOUT-0004', 7, '"ram0", "next"')
case('shape_pin_in_blockage.xml',
     text({6: '    <pin name="p0"><rect x0="1200" y0="1200" x1="1300" y1="1300"/></pin>'}),
     'LAYOUT-0005', 6, 'net "n0" pin "p0": the pin shape lies inside blockage "ram0"')
case('pin_outside_boundary.xml', text({7: '    <pin name="p1" x="10001" y="9000"/>'}), 'LAYOUT-0006', 7,
     'net "n0" pin "p1"')
case('shape_pin_outside_boundary.xml',
     text({7: '    <pin name="p1"><rect x0="10001" y0="0" x1="10002" y1="5"/></pin>'}), 'LAYOUT-0006', 7,
     'net "n0" pin "p1"')
case('route_unknown_net.xml', text(None, {9: ROUTES('    <route net="n9" status="failed" reason="x"/>')}),
     'LAYOUT-0010', 10, 'route "n9"')
case('route_twice.xml',
     text(None, {9: ['  <routes>', '    <route net="n0" status="failed"/>', '    <route net="n0" status="failed"/>',
                     '  </routes>']}),
     'LAYOUT-0011', 11, 'route "n0"')
case('orientations_one_direction.xml', text(None, {4: '  <rules orientations="c:0,180"/>'}), 'LAYOUT-0014', 4,
     'c:0,180')
# Warnings: the file is usable, `taut check` exits 0 (lenient_ok does not apply: '-').
case('net_one_pin.xml', text({7: ''}), 'LAYOUT-0007', 5, 'net "n0"', '-', 'warning')
case('sketch_off_pin.xml', text(None, {8: '    <sketch points="100,100 5000,5000 8000,9000"/>'}), 'LAYOUT-0008', 8,
     'net "n0" sketch: ends at (8000,9000)', '-', 'warning')
case('sketch_three_pins.xml',
     text(None, {8: ['    <pin name="p2" x="9000" y="100"/>', '    <sketch points="100,100 9000,9000"/>']}),
     'LAYOUT-0009', 9, 'net "n0" sketch', '-', 'warning')

with open(os.path.join(HERE, 'EXPECTED.tsv'), 'w') as f:
    f.write('# Bad-input corpus: one file per case, written by make_corpus.py (edit that, then rerun it).\n'
            '# Columns (tab-separated): file, expected_code, expected_line, object, lenient_ok, severity.\n'
            '#  expected_code: the code of the FIRST diagnostic of that severity (a trailing * would\n'
            '#    match any code with that prefix; none is used now).\n'
            '#  expected_line: its line; 0 = no line (whole-file problems: empty, compressed).\n'
            '#  object: a substring its message contains; - when none is asserted.\n'
            '#  lenient_ok: yes = with --lenient the file has no error left (only warnings); no = still\n'
            '#    an error; - = does not apply (warning rows).\n'
            '#  severity: error = `taut check` exits 2 (invalid input, nothing else done);\n'
            '#    warning = the file is valid, `taut check` prints the warning and exits 0.\n'
            'file\texpected_code\texpected_line\tobject\tlenient_ok\tseverity\n')
    for r in rows:
        f.write('\t'.join(r) + '\n')
print(len(rows), 'cases')
