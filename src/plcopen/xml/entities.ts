// Entity and character references of XML text (the five predefined entities, no DTD entities).

const ENTITIES: Record<string, string> = { lt: '<', gt: '>', amp: '&', quot: '"', apos: "'" };

/** Decodes entity and character references; `fail` gets the offset in `s` of the bad reference. */
export function decodeEntities(s: string, fail: (msg: string, at: number) => never): string {
  if (s.indexOf('&') === -1) return s;
  return s.replace(/&([^;&\s]*);?/g, (m, body: string, at: number) => {
    if (!m.endsWith(';')) fail(`"&" must start an entity such as &amp;`, at);
    if (body.startsWith('#x') || body.startsWith('#X')) {
      const n = parseInt(body.slice(2), 16);
      if (Number.isNaN(n)) fail(`bad character reference "${m}"`, at);
      return String.fromCodePoint(n);
    }
    if (body.startsWith('#')) {
      const n = parseInt(body.slice(1), 10);
      if (Number.isNaN(n)) fail(`bad character reference "${m}"`, at);
      return String.fromCodePoint(n);
    }
    const e = ENTITIES[body];
    if (e === undefined) fail(`unknown entity "${m}"`, at);
    return e;
  });
}

/** Entities were checked while parsing: decoding again cannot fail. */
export const checked = (msg: string): never => {
  throw new Error(`internal: ${msg}`);
};
