// Bad input gives a clear, located error and never an exception.
import { describe, expect, it } from 'vitest';
import { importPlcopen } from '../../src/plcopen/importPlcopen';
import { fixture } from './fixtures';

const errorOf = (text: string) => {
  const r = importPlcopen(text);
  if (r.ok) throw new Error('expected the import to fail');
  return r.errors[0]!;
};

describe('PLCopen import errors', () => {
  it('text that is not XML names the line', () => {
    const e = errorOf('{"format": "rungsmith-project"}');
    expect(e.message).toMatch(/not well-formed XML: .*not XML/);
    expect(e.line).toBe(1);
  });

  it('a tag left open reports where the file ends', () => {
    const e = errorOf(
      '<?xml version="1.0"?>\n<project xmlns="http://www.plcopen.org/xml/tc6_0201">\n  <types>\n',
    );
    expect(e.message).toContain('the file ends inside <types>');
    expect(e.line).toBe(4);
  });

  it('another root element is refused', () => {
    const e = errorOf('<?xml version="1.0"?>\n<svg xmlns="http://www.w3.org/2000/svg"></svg>');
    expect(e).toMatchObject({ line: 2, element: 'svg' });
    expect(e.message).toContain('expected <project>');
  });

  it('an unknown namespace is refused', () => {
    expect(errorOf('<project xmlns="http://example.com/other"><types/></project>').message).toContain(
      'unknown namespace',
    );
  });

  it('a connection to a localId that does not exist drops that wire only, with a warning naming the element, its localId and line', () => {
    const text = fixture('connector-continuation.xml').replace(
      '<connection refLocalId="2">',
      '<connection refLocalId="99">',
    );
    const whole = importPlcopen(fixture('connector-continuation.xml'));
    const r = importPlcopen(text);
    expect(r.ok).toBe(true);
    if (!r.ok || !whole.ok) return;
    const w = r.report.warnings.find((x) => x.message.includes('localId 99, which does not exist'));
    expect(w).toMatchObject({ element: 'contact', localId: '3', pou: 'Main' });
    expect(w!.line).toBeGreaterThan(20);
    expect(w!.message).toContain('that wire is dropped');
    // Everything else is there: the same POUs, networks and element count less nothing.
    expect(r.project.pous.map((p) => p.name)).toEqual(whole.project.pous.map((p) => p.name));
    expect(r.project.pous[0]!.networks.flatMap((n) => n.elements.filter((e) => e.kind !== 'link')).length).toBe(
      whole.project.pous[0]!.networks.flatMap((n) => n.elements.filter((e) => e.kind !== 'link')).length,
    );
  });

  it('two objects with one localId are refused', () => {
    const text = fixture('connector-continuation.xml').replace(
      '<contact localId="3"',
      '<contact localId="2"',
    );
    expect(errorOf(text).message).toContain('localId 2 is used twice');
  });

  it('a POU body in no known language is refused', () => {
    const text = fixture('jump-label-return.xml').replace(/<body>[\s\S]*<\/body>/, '<body><Python/></body>');
    expect(errorOf(text)).toMatchObject({ element: 'pou', pou: 'Main' });
  });

  it('damage inside pin offsets and wire routes (which the import does not read) is still located', () => {
    const text = fixture('connector-continuation.xml');
    const lines = text.split('\n');
    const route = lines.findIndex((l) => l.includes('<connection refLocalId="1"><position'));
    expect(route).toBeGreaterThan(0);
    const broken = [...lines];
    broken[route] = broken[route]!.replace('<position x="50"', '<position x=50');
    expect(errorOf(broken.join('\n'))).toMatchObject({ line: route + 1 });
    const twice = [...lines];
    twice[route] = twice[route]!.replace('<relPosition x="0"', '<relPosition x="0" x="1"');
    const e = errorOf(twice.join('\n'));
    expect(e.line).toBe(route + 1);
    expect(e.message).toContain('attribute "x" repeated');
  });

  it('never throws on damaged files: every truncation of a real file gives a result', () => {
    const text = fixture('corpus/virajdesai__05_xor_xnor.xml');
    for (let cut = 0; cut < text.length; cut += 97) {
      const r = importPlcopen(text.slice(0, cut));
      expect(typeof r.ok).toBe('boolean');
      if (!r.ok) expect(r.errors[0]!.message.length).toBeGreaterThan(0);
    }
  });
});
