// Data types that vendor libraries declare and projects use without declaring them, like
// vendorBlocks.ts ships vendor blocks. Beremiz's SVGHMI library (svghmi/pous.xml, svghmi/hmi_tree.py)
// declares its HMI variable types as plain derived types of elementary ones: a variable of type
// HMI_BOOL is a BOOL that the HMI server publishes. In the simulator they behave as their base.
// HMI_NODE (a node of the HMI tree, declared before the HMI_* variables of a POU) and the older
// HMI_CLASS / HMI_LABEL markers carry no value for the PLC program: Beremiz declares them over BOOL.
// CODESYS's BIT (a BOOL packed in a structure) and its register-wide __X types are aliases too.
// A project's own data type of the same name wins over these.
import type { DataType } from './project';

export interface VendorTypeLibrary {
  readonly name: string;
  /** Where the vendor declares them. */
  readonly source: string;
  readonly types: readonly DataType[];
}

const alias = (name: string, base: string, comment: string): DataType => ({ name, def: { kind: 'alias', base }, comment });

export const VENDOR_TYPE_LIBRARIES: readonly VendorTypeLibrary[] = [
  {
    name: 'SVGHMI',
    source: 'Beremiz svghmi/pous.xml',
    types: [
      alias('HMI_BOOL', 'BOOL', 'SVGHMI: a BOOL published to the HMI'),
      alias('HMI_INT', 'INT', 'SVGHMI: an INT published to the HMI'),
      alias('HMI_REAL', 'REAL', 'SVGHMI: a REAL published to the HMI'),
      alias('HMI_STRING', 'STRING', 'SVGHMI: a STRING published to the HMI'),
      alias('HMI_NODE', 'BOOL', 'SVGHMI: a node of the HMI tree (no value for the program)'),
      alias('HMI_CLASS', 'BOOL', 'SVGHMI (older versions): an HMI class marker'),
      alias('HMI_LABEL', 'BOOL', 'SVGHMI (older versions): an HMI label marker'),
    ],
  },
  {
    // CODESYS V3 (helpme-codesys.com, "Data types"): BIT is a BOOL packed as one bit of a
    // structure or function block; the __X types are the target's register width (here the
    // 64-bit one of CODESYS Control Win/Linux x64).
    name: 'CODESYS',
    source: 'CODESYS V3 data types',
    types: [
      alias('BIT', 'BOOL', 'CODESYS: a BOOL stored as one bit of a structure; behaves as a BOOL'),
      alias('__XWORD', 'LWORD', 'CODESYS: a register-wide WORD (LWORD on 64-bit targets, DWORD on 32-bit ones); taken as LWORD'),
      alias('__UXINT', 'ULINT', 'CODESYS: a register-wide unsigned integer (ULINT on 64-bit targets, UDINT on 32-bit ones); taken as ULINT'),
      alias('__XINT', 'LINT', 'CODESYS: a register-wide signed integer (LINT on 64-bit targets, DINT on 32-bit ones); taken as LINT'),
    ],
  },
];

const BY_NAME = new Map<string, DataType>(VENDOR_TYPE_LIBRARIES.flatMap((l) => l.types.map((t) => [t.name, t] as const)));

/** A vendor data type by (case-insensitive) name. */
export const vendorType = (name: string): DataType | undefined => BY_NAME.get(name.trim().toUpperCase());
