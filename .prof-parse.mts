import { readFileSync } from 'node:fs';
import { parseXml } from './src/plcopen/xml/parse.ts';
const t = readFileSync('/tmp/gen2000.xml', 'utf8');
for (let i = 0; i < 5; i++) { const t0 = performance.now(); parseXml(t); console.log('parse', (performance.now() - t0).toFixed(0)); }
