// The XML reader behind the PLCopen import: a flat document read by index, and element views.
import { describe, expect, it } from 'vitest';
import {
  child,
  childrenNamed,
  deepText,
  parseXml,
  parseXmlDoc,
  XmlSyntaxError,
} from '../../src/plcopen/xml/parse';

const syntaxError = (xml: string): XmlSyntaxError => {
  try {
    parseXml(xml);
  } catch (e) {
    if (e instanceof XmlSyntaxError) return e;
    throw e;
  }
  throw new Error('parsed without error');
};

describe('XML document', () => {
  it('reads names, prefixes, attributes and children in order', () => {
    const root = parseXml(
      `<?xml version="1.0"?>\n<!-- head --><p:project xmlns:p="urn:x" a='1' b = "two">\n  <item n="1"/><other/><item n="2">x</item>\n</p:project>`,
    );
    expect(root.name).toBe('project');
    expect(root.qname).toBe('p:project');
    expect(root.attrs).toEqual({ 'xmlns:p': 'urn:x', a: '1', b: 'two' });
    expect(root.children.map((c) => c.name)).toEqual(['item', 'other', 'item']);
    expect(childrenNamed(root, 'item').map((c) => c.attrs.n)).toEqual(['1', '2']);
    expect(child(root, 'missing')).toBeUndefined();
    expect(child(root, 'item')!.text).toBe('');
    expect(childrenNamed(root, 'item')[1]!.text).toBe('x');
  });

  it('decodes entities and keeps CDATA verbatim, dropping whitespace-only runs', () => {
    const root = parseXml(
      '<r v="a &lt; b &amp; &#x41;&#66;" q=\'say "hi"\' gt="a>b">\n  x &gt; y<![CDATA[ <raw> & ]]>\n</r>',
    );
    expect(root.attrs.v).toBe('a < b & AB');
    expect(root.attrs.q).toBe('say "hi"');
    expect(root.attrs.gt).toBe('a>b');
    expect(root.text).toBe('\n  x > y <raw> & ');
  });

  it('gathers formatted text through nested xhtml', () => {
    const root = parseXml(
      '<documentation><xhtml:p>First</xhtml:p><xhtml:p>Second <b>bold</b></xhtml:p></documentation>',
    );
    expect(deepText(root)).toBe('First\nSecond bold');
  });

  it('keeps source offsets of every element for verbatim copies', () => {
    const src = '<a>\n  <b k="1"><c/></b>\n</a>';
    const b = child(parseXml(src), 'b')!;
    expect(src.slice(b.offset, b.end)).toBe('<b k="1"><c/></b>');
  });

  it('leaves skipped elements out of the document but still checks them', () => {
    const skip = (parent: string, name: string) =>
      name === 'relPosition' || (name === 'position' && parent === 'connection');
    const doc = parseXmlDoc(
      '<cp><relPosition x="1" y="2"/><connection refLocalId="7"><position x="1" y="1"/><position x="2" y="2"/></connection><position x="5"/></cp>',
      { skip },
    );
    const root = doc.element(0);
    expect(root.children.map((c) => c.name)).toEqual(['connection', 'position']);
    expect(child(root, 'connection')!.children).toHaveLength(0);
    expect(child(root, 'position')!.attrs.x).toBe('5');
    expect(() => parseXmlDoc('<cp><relPosition x="1" x="2"/></cp>', { skip })).toThrow(
      /attribute "x" repeated/,
    );
    expect(() => parseXmlDoc('<cp><relPosition x="1"></cp>', { skip })).toThrow(/does not match/);
  });

  it('reads numbers and ids by index without building elements', () => {
    const doc = parseXmlDoc(
      '<r><e localId="42" x="-3.5" y="12" z="007" w="abc" big="12345678901" zero="0"/></r>',
    );
    const e = doc.firstChild[0]!;
    expect(doc.name(e)).toBe('e');
    expect(doc.attrIndexNumber(e, doc.id('localId'))).toBe(42);
    expect(doc.attrIndexNumber(e, doc.id('z'))).toBe(-1);
    expect(doc.attrIndexNumber(e, doc.id('big'))).toBe(-1);
    expect(doc.attrIndexNumber(e, doc.id('zero'))).toBe(0);
    expect(doc.attrNumber(e, doc.id('big'))).toBe(12345678901);
    expect(doc.attrNumber(e, doc.id('z'))).toBe(7);
    expect(doc.attrNumber(e, doc.id('x'))).toBe(-3.5);
    expect(doc.attrNumber(e, doc.id('y'))).toBe(12);
    expect(doc.attrNumber(e, doc.id('w'))).toBe(0);
    expect(doc.id('never')).toBe(-1);
    expect(doc.attr(e, doc.id('never'))).toBeUndefined();
  });

  it.each([
    ['not XML at all', 'hello', /this is not XML/, 1, 1],
    ['a mismatched end tag', '<a>\n  <b></c>\n</a>', /end tag <\/c> does not match <b>/, 2, 6],
    ['an unquoted attribute', '<a x=1/>', /must be quoted/, 1, 6],
    ['an unknown entity', '<a>\n&nbsp;</a>', /unknown entity/, 2, 1],
    ['"<" in a value', '<a x="<"/>', /"<" in the value/, 1, 6],
    ['a truncated file', '<a><b>', /the file ends inside <b>/, 1, 7],
    ['two roots', '<a/><b/>', /more than one root/, 1, 5],
    ['a repeated attribute', '<a x="1" x="2"/>', /repeated/, 1, 10],
  ])('reports %s with its line and column', (_what, xml, message, line, column) => {
    const e = syntaxError(xml);
    expect(e.message).toMatch(message);
    expect([e.line, e.column]).toEqual([line, column]);
  });
});
