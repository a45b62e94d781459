import { readFileSync } from 'node:fs';
import { importPlcopen } from './src/plcopen/importPlcopen.ts';
import { parseXml } from './src/plcopen/xml/parse.ts';
const t = readFileSync(process.argv[2]!, 'utf8');
for (let i = 0; i < 3; i++) { let t0 = performance.now(); parseXml(t); const p = performance.now() - t0; t0 = performance.now(); const r = importPlcopen(t); console.log('parse', p.toFixed(0), 'import', (performance.now() - t0).toFixed(0), r.ok); }
