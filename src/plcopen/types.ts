// Shapes shared by PLCopen import and export.

export const TC6_0201 = 'http://www.plcopen.org/xml/tc6_0201';
export const TC6_0200 = 'http://www.plcopen.org/xml/tc6_0200';
export const TC6_V10 = 'http://www.plcopen.org/xml/tc6.xsd';
export const XHTML_NS = 'http://www.w3.org/1999/xhtml';
/** addData names Rungsmith writes (and reads back) for what PLCopen has no element for. */
export const RS_NS = 'https://rungsmith.dev/plcopen';
export const RS_COIL = `${RS_NS}/coil`;
export const RS_CONTACT = `${RS_NS}/contact`;
export const RS_VARIABLE = `${RS_NS}/variable`;
export const RS_NETWORK = `${RS_NS}/network`;
export const RS_PROJECT = `${RS_NS}/project`;

/** Where a finding was made in the XML: line, element and localId when known. */
export interface XmlLocation {
  readonly line?: number;
  readonly element?: string;
  readonly localId?: string;
  readonly pou?: string;
}

export interface ImportIssue extends XmlLocation {
  readonly message: string;
}

export interface ImportReport {
  /** The namespace the file was written in (tc6_0201, tc6_0200, ...). */
  readonly namespace: string;
  /** Tool that wrote the file (fileHeader companyName/productName). */
  readonly producer: string;
  /** LD POUs imported, with their network counts. */
  readonly pous: readonly { readonly name: string; readonly networks: number; readonly from: string }[];
  /** Things dropped or changed on the way in. */
  readonly warnings: readonly ImportIssue[];
  /**
   * What the import did that loses nothing but a user should know: wires drawn through connector
   * pairs (one line per network), VAR_EXTERNALs whose global is declared outside the file.
   */
  readonly notes: readonly ImportIssue[];
  /** Why the project runs under the profile it got (profileChoice.ts): `semantics profile openplc: ...`. */
  readonly profileReason: string;
}

export type ImportResult =
  | { readonly ok: true; readonly project: import('../model/project').Project; readonly report: ImportReport }
  | { readonly ok: false; readonly errors: readonly ImportIssue[] };

/** What Rungsmith keeps from a PLCopen file that the model cannot express (stored in `extensions.plcopen`). */
export interface PreservedProject {
  /** Raw `<data>` elements from the project's and contentHeader's addData. */
  readonly addData?: readonly string[];
  /** Raw `<dataTypes>` children (user types are kept, not interpreted). */
  readonly dataTypes?: readonly string[];
  /**
   * Raw `<pou>` elements in languages other than LD, as projects imported before non-LD POUs became
   * POUs of their own kept them; still exported (unless a POU of that name is in the project).
   */
  readonly otherPous?: readonly string[];
  /** Namespace declarations used by preserved XML (prefix -> URI). */
  readonly namespaces?: Readonly<Record<string, string>>;
  /** Configuration and resource names. */
  readonly configuration?: string;
  readonly resource?: string;
}

export interface PreservedPou {
  readonly addData?: readonly string[];
  /**
   * A POU in ST, IL, SFC or FBD (not converted to LD): its `<pou>` element as written in the file,
   * exported again byte for byte while `fingerprint` still matches the POU (name, kind, interface,
   * source, comment: see pouFingerprint). Once one of them is edited the `<pou>` is written anew
   * from the model, with `actions` and `transitions` (raw, SFC) kept and the body from `source`.
   */
  readonly pou?: string;
  readonly fingerprint?: string;
  readonly actions?: string;
  readonly transitions?: string;
  /** A graphical body in the legacy TC6 v1.0 format: `source` cannot go into a v2.01 file (exported empty). */
  readonly legacyBody?: true;
}

export interface PreservedNetwork {
  /** Raw body objects kept verbatim (vendorElement, error, unknown addData holders). */
  readonly objects?: readonly string[];
  /** Raw `<data>` elements per element id. */
  readonly elementData?: Readonly<Record<string, readonly string[]>>;
}

export const preserved = <T>(ext: Readonly<Record<string, unknown>> | undefined): T | undefined =>
  (ext?.plcopen as T | undefined) ?? undefined;
