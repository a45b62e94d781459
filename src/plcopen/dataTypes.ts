// PLCopen user data types <-> Project.dataTypes, and the non-elementary parts of variable
// declarations: anonymous array types (`<type><array>` <-> the type text `ARRAY[1..3] OF INT`)
// and structured initial values (`<arrayValue>` with repetitionValue <-> `[32(0), 30(1)]`,
// `<structValue>` <-> `(X := 1, Y := 2)`).
//
// Read: enum, struct, array, subrangeSigned/subrangeUnsigned and derived/elementary (an alias).
// Anonymous types inside a declaration (a variable's or a member's `<type>`: `<array>`, `<struct>`,
// `<enum>`, `<subrangeSigned>`) become the type texts model/dataTypes.ts resolves
// (`ARRAY[0..9] OF INT`, `STRUCT X : INT; END_STRUCT`, `(Idle, Run)`, `INT (0..100)`) and are
// written back as the same anonymous elements. Not read (kept raw for export, the caller warns):
// pointers.
import { anonymousText, anonymousType, elementaryOf, formatInitial, parseDims, parseInitial, type InitValue } from '../model/dataTypes';
import type { DataType, DataTypeDef } from '../model/project';
import { child, childrenNamed, deepText, type XmlElement } from './xml/parse';
import { unqualifiedType } from './codesys';
import type { XmlWriter } from './xml/write';

export type Warn = (message: string, el?: XmlElement) => void;

const STRING_TYPES: Record<string, string> = { string: 'STRING', wstring: 'WSTRING' };

class Unsupported extends Error {
  constructor(
    message: string,
    readonly el: XmlElement,
  ) {
    super(message);
  }
}

/** The type text of a type element (`<INT/>`, `<derived name=".."/>`, `<string length="20"/>`, `<array>`). */
function typeTextOf(t: XmlElement): string {
  if (t.name === 'derived') {
    const name = unqualifiedType(t.attrs.name ?? 'BOOL');
    // CODESYS writes REFERENCE TO / POINTER TO as a derived type name.
    if (/^(REFERENCE|POINTER)\s+TO\s/i.test(name.trim())) throw new Unsupported(`a ${name.trim()} member is not supported`, t);
    return name;
  }
  if (STRING_TYPES[t.name]) return t.attrs.length ? `${STRING_TYPES[t.name]!}[${t.attrs.length}]` : STRING_TYPES[t.name]!;
  if (t.name === 'array') {
    const dims = childrenNamed(t, 'dimension').map((d) => `${d.attrs.lower ?? '0'}..${d.attrs.upper ?? '0'}`);
    const base = child(t, 'baseType')?.children[0];
    if (!base) throw new Unsupported('an array without a base type', t);
    return `ARRAY[${dims.join(', ')}] OF ${typeTextOf(base)}`;
  }
  if (['enum', 'struct', 'subrangeSigned', 'subrangeUnsigned'].includes(t.name))
    return anonymousText(defOf(t) as Extract<DataTypeDef, { kind: 'enum' | 'struct' | 'subrange' }>);
  if (t.name === 'pointer') throw new Unsupported('a pointer type inside a declaration is not supported', t);
  return t.name.toUpperCase();
}

/**
 * The type text of a variable's `<type>`: elementary, derived, STRING[n], or an anonymous array,
 * structure, enumeration or subrange. Undefined (after a warning) for a pointer.
 */
export function readTypeText(typeEl: XmlElement | undefined, warn: Warn): string | undefined {
  const t = typeEl?.children[0];
  if (!t) return 'BOOL';
  try {
    return typeTextOf(t);
  } catch (e) {
    if (!(e instanceof Unsupported)) throw e;
    warn(e.message, e.el);
    return undefined;
  }
}

/** The text of an initial value element (`<initialValue>`) or undefined when absent/empty. */
export function readValueText(iv: XmlElement | undefined): string | undefined {
  const v = iv && valueOf(iv);
  return v ? formatInitial(v) : undefined;
}

function valueOf(el: XmlElement): InitValue | undefined {
  const simple = child(el, 'simpleValue');
  if (simple) return simple.attrs.value !== undefined ? { k: 'simple', text: simple.attrs.value } : undefined;
  const arr = child(el, 'arrayValue');
  if (arr)
    return {
      k: 'array',
      items: childrenNamed(arr, 'value').map((v) => {
        const inner = valueOf(v);
        return { count: Number(v.attrs.repetitionValue ?? '1') || 1, ...(inner ? { value: inner } : {}) };
      }),
    };
  const st = child(el, 'structValue');
  if (st)
    return {
      k: 'struct',
      members: childrenNamed(st, 'value').flatMap((v) => {
        const inner = valueOf(v);
        return inner ? [{ name: v.attrs.member ?? '', value: inner }] : [];
      }),
    };
  return undefined;
}

function defOf(base: XmlElement): DataTypeDef {
  switch (base.name) {
    case 'enum':
      return { kind: 'enum', values: childrenNamed(child(base, 'values') ?? base, 'value').map((v) => v.attrs.name ?? '') };
    case 'struct':
      return {
        kind: 'struct',
        members: childrenNamed(base, 'variable').map((v) => {
          const t = child(v, 'type')?.children[0];
          if (!t) throw new Unsupported(`the member ${v.attrs.name} has no type`, v);
          const initial = readValueText(child(v, 'initialValue'));
          const doc = child(v, 'documentation');
          const comment = doc ? deepText(doc).trim() : '';
          return { name: v.attrs.name ?? '', type: typeTextOf(t), ...(initial !== undefined ? { initial } : {}), ...(comment ? { comment } : {}) };
        }),
      };
    case 'array': {
      const dims = parseDims(childrenNamed(base, 'dimension').map((d) => `${d.attrs.lower}..${d.attrs.upper}`).join(','));
      if (typeof dims === 'string') throw new Unsupported(`an array dimension: ${dims}`, base);
      const of = child(base, 'baseType')?.children[0];
      if (!of) throw new Unsupported('an array without a base type', base);
      return { kind: 'array', dims, of: typeTextOf(of) };
    }
    case 'subrangeSigned':
    case 'subrangeUnsigned': {
      const range = child(base, 'range');
      const of = child(base, 'baseType')?.children[0];
      if (!range || !of) throw new Unsupported('a subrange without its range or base type', base);
      return { kind: 'subrange', base: typeTextOf(of), lower: Number(range.attrs.lower), upper: Number(range.attrs.upper) };
    }
    case 'pointer':
      throw new Unsupported('a pointer type is not supported', base);
    default:
      return { kind: 'alias', base: typeTextOf(base) };
  }
}

/**
 * The data types of `<types><dataTypes>`. Those Rungsmith cannot read come back in `raw` (their
 * XML, written back unchanged on export) after a warning.
 */
export function readDataTypes(
  dataTypes: XmlElement | undefined,
  warn: Warn,
  raw: (el: XmlElement) => string,
  /** `<dataType>` elements found elsewhere (CODESYS: the application's, in the resource's addData). */
  more: readonly XmlElement[] = [],
): { types: DataType[]; raw: string[] } {
  const types: DataType[] = [];
  const kept: string[] = [];
  for (const dt of [...(dataTypes ? childrenNamed(dataTypes, 'dataType') : []), ...more]) {
    const base = child(dt, 'baseType')?.children[0];
    try {
      if (!base) throw new Unsupported('it has no base type', dt);
      const def = defOf(base);
      const initial = readValueText(child(dt, 'initialValue'));
      const doc = child(dt, 'documentation');
      const comment = doc ? deepText(doc).trim() : '';
      types.push({ name: dt.attrs.name ?? '', def, ...(initial !== undefined ? { initial } : {}), ...(comment ? { comment } : {}) });
    } catch (e) {
      if (!(e instanceof Unsupported)) throw e;
      kept.push(raw(dt));
      warn(`data type "${dt.attrs.name}": ${e.message}; it is kept for export but variables cannot use it`, e.el);
    }
  }
  return { types, raw: kept };
}

// ---- export ----

const ARRAY_TEXT = /^ARRAY\s*\[(.*?)\]\s*OF\s+(.+)$/is;

/** Writes a type text: anonymous arrays, structures, enumerations and subranges as such, the rest through `elementary`. */
export function writeTypeText(w: XmlWriter, text: string, elementary: (w: XmlWriter, t: string) => void): void {
  const anonymous = anonymousType(text);
  if (anonymous && typeof anonymous !== 'string') {
    writeDef(w, anonymous, (t) => writeTypeText(w, t, elementary));
    return;
  }
  const m = ARRAY_TEXT.exec(text.trim());
  const dims = m ? parseDims(m[1]!) : undefined;
  if (!m || typeof dims === 'string' || !dims) {
    elementary(w, text);
    return;
  }
  w.open('array', undefined, () => {
    for (const d of dims) w.empty('dimension', { lower: String(d.lower), upper: String(d.upper) });
    w.open('baseType', undefined, () => writeTypeText(w, m[2]!.trim(), elementary));
  });
}

/** Writes `<initialValue>` for an initial value text (simple, array with repetitions, struct). */
export function writeInitialValue(w: XmlWriter, text: string): void {
  const v = parseInitial(text);
  w.open('initialValue', undefined, () => writeValue(w, 'error' in v ? { k: 'simple', text } : v));
}

function writeValue(w: XmlWriter, v: InitValue): void {
  switch (v.k) {
    case 'simple':
      w.empty('simpleValue', { value: v.text });
      return;
    case 'array':
      w.open('arrayValue', undefined, () => {
        for (const it of v.items) {
          const attrs = it.count !== 1 ? { repetitionValue: String(it.count) } : undefined;
          if (it.value) w.open('value', attrs, () => writeValue(w, it.value!));
          else w.empty('value', attrs);
        }
      });
      return;
    case 'struct':
      w.open('structValue', undefined, () => {
        for (const m of v.members) w.open('value', { member: m.name }, () => writeValue(w, m.value));
      });
  }
}

/** Writes the project's data types (then `raw` ones kept from an import, when not redeclared). */
export function writeDataTypes(w: XmlWriter, types: readonly DataType[], raw: readonly string[], elementary: (w: XmlWriter, t: string) => void): void {
  if (types.length === 0 && raw.length === 0) {
    w.empty('dataTypes');
    return;
  }
  const names = new Set(types.map((t) => t.name.toUpperCase()));
  const typeOf = (t: string) => writeTypeText(w, t, elementary);
  w.open('dataTypes', undefined, () => {
    for (const dt of types)
      w.open('dataType', { name: dt.name }, () => {
        w.open('baseType', undefined, () => writeDef(w, dt.def, typeOf));
        if (dt.initial) writeInitialValue(w, dt.initial);
        if (dt.comment) w.formatted('documentation', dt.comment);
      });
    for (const r of raw) if (!names.has((/<dataType\s[^>]*name="([^"]*)"/.exec(r)?.[1] ?? '').toUpperCase())) w.raw(r);
  });
}

/** The element of a definition (`<enum>`, `<struct>`, `<array>`, `<subrangeSigned>`, an alias's base type). */
function writeDef(w: XmlWriter, d: DataTypeDef, typeOf: (t: string) => void): void {
  switch (d.kind) {
    case 'enum':
      w.open('enum', undefined, () => w.open('values', undefined, () => d.values.forEach((v) => w.empty('value', { name: v }))));
      return;
    case 'struct':
      w.open('struct', undefined, () => {
        for (const m of d.members)
          w.open('variable', { name: m.name }, () => {
            w.open('type', undefined, () => typeOf(m.type));
            if (m.initial) writeInitialValue(w, m.initial);
            if (m.comment) w.formatted('documentation', m.comment);
          });
      });
      return;
    case 'array':
      w.open('array', undefined, () => {
        for (const x of d.dims) w.empty('dimension', { lower: String(x.lower), upper: String(x.upper) });
        w.open('baseType', undefined, () => typeOf(d.of));
      });
      return;
    case 'subrange':
      w.open(d.lower >= 0 && /^(U|BYTE$|WORD$|DWORD$|LWORD$)/.test(elementaryOf(d.base) ?? '') ? 'subrangeUnsigned' : 'subrangeSigned', undefined, () => {
        w.empty('range', { lower: String(d.lower), upper: String(d.upper) });
        w.open('baseType', undefined, () => typeOf(d.base));
      });
      return;
    case 'alias':
      typeOf(d.base);
  }
}
