// Legacy PLCopen TC6 v1.0 text upgraded to v2.01, as Beremiz reads such files. Formatted text
// (ST, IL, comments, documentation) is bare CDATA in v1.0 and inside <xhtml:p> in v2.01; a
// transition's graphical condition is `<condition><connection .../></condition>` in v1.0 and
// `<condition><connectionPointIn><connection .../></connectionPointIn></condition>` in v2.01; an
// action of an action block has a localId and a relPosition in v2.01 only. The rest of an SFC chart
// (steps, transitions, divergences, jumps, actions and transitions declared by name) is written alike.
import { child, parseXml, type XmlElement } from './xml/parse';

/** TC6 v1.0 wrote formatted text as bare CDATA; v2.01 wants it inside <xhtml:p> (Beremiz upgrades the same way). */
export function upgradeLegacyText(xml: string): string {
  return xml.replace(
    /<(content|documentation|ST|IL|alternativeText)>(\s*)<!\[CDATA\[([\s\S]*?)\]\]>(\s*)<\/\1>/g,
    (_m, tag: string, _a: string, body: string) => `<${tag}><xhtml:p><![CDATA[${body}]]></xhtml:p></${tag}>`,
  );
}

/** A v1.0 graphical condition's wires, moved into the connectionPointIn v2.01 wants. */
function upgradeConditions(xml: string): string {
  return xml.replace(
    /<condition>(\s*)(<connection\b[\s\S]*?)(\s*)<\/condition>/g,
    (_m, lead: string, wires: string, trail: string) =>
      `<condition>${lead}<connectionPointIn>${wires}</connectionPointIn>${trail}</condition>`,
  );
}

/**
 * The actions of a v1.0 action block, given what v2.01 requires of each: a localId (new, past the
 * body's largest) and a relPosition (one row of the block's height each, as Beremiz draws them).
 */
function upgradeActionBlocks(xml: string): string {
  let next = Math.max(0, ...[...xml.matchAll(/\blocalId="(\d+)"/g)].map((m) => Number(m[1]))) + 1;
  return xml.replace(/<actionBlock\b[\s\S]*?<\/actionBlock>/g, (block) => {
    let row = 0;
    return block.replace(/<action\b(?![^>]*\blocalId=)([^>]*?)(\/?)>/g, (_m, attrs: string, empty: string) => {
      const head = `<action localId="${next++}"${attrs}>`;
      const rel = `<relPosition x="0" y="${20 * row++}"/>`;
      return empty ? `${head}${rel}</action>` : `${head}${rel}`;
    });
  });
}

/** A v1.0 `<pou>` with an SFC body as v2.01 text, and that text parsed (the pou and its SFC element). */
export function upgradeLegacySfc(pouXml: string): { text: string; pou: XmlElement; sfc: XmlElement } {
  const text = upgradeActionBlocks(upgradeConditions(upgradeLegacyText(pouXml)));
  const pou = parseXml(text);
  const sfc = child(child(pou, 'body') ?? pou, 'SFC');
  if (!sfc) throw new Error('the legacy SFC body has no <SFC> element');
  return { text, pou, sfc };
}
