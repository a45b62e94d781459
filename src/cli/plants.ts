// `rungsmith plants [NAME]`: the machines to control, their I/O maps, faults and quantities.
import { PLANTS, requirePlant } from '../plant/machines';
import type { PlantModel } from '../plant/types';
import { UsageError } from './io';

function describe(m: PlantModel, withTask: boolean): string {
  const out = [`${m.id}: ${m.title}`];
  if (withTask) out.push('', ...m.task.split('\n').map((l) => `  ${l}`), '');
  out.push('  I/O:');
  for (const p of m.points)
    out.push(
      `    ${p.address.padEnd(8)}${p.name.padEnd(12)}${p.type.padEnd(6)}${(p.kind + (p.control ? ` (${p.control})` : '')).padEnd(19)}${p.comment}`,
    );
  out.push('  Faults:');
  for (const f of m.faults) out.push(`    ${f.id.padEnd(20)}${f.title}`);
  out.push('  Quantities:');
  for (const q of m.quantities)
    out.push(
      `    ${`${m.id}.${q.name}`.padEnd(20)}${q.type.padEnd(6)}${(q.unit ?? '').padEnd(5)}${q.comment}`,
    );
  return out.join('\n');
}

export function listPlants(name?: string): string {
  if (name === undefined) return `${PLANTS.map((m) => describe(m, false)).join('\n\n')}\n`;
  try {
    return `${describe(requirePlant(name), true)}\n`;
  } catch (e) {
    throw new UsageError((e as Error).message);
  }
}
