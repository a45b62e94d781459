// Validation of exported XML against the PLCopen TC6 v2.01 schema (xmllint compiled to wasm, in process).
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { validateXML } from 'xmllint-wasm';

const SCHEMA = readFileSync(fileURLToPath(new URL('../../schema/tc6_xml_v201.xsd', import.meta.url)), 'utf8');

/** The schema errors of an XML text ([] when valid). */
export async function schemaErrors(xml: string, fileName = 'export.xml'): Promise<string[]> {
  const r = await validateXML({
    xml: [{ fileName, contents: xml }],
    schema: [{ fileName: 'tc6_xml_v201.xsd', contents: SCHEMA }],
  });
  return r.valid ? [] : r.errors.map((e) => e.message ?? e.rawMessage);
}
