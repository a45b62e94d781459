// `rungsmith plants [NAME]`: the machines to control, their I/O maps, faults and quantities.
import { PLANTS, requirePlant } from '../plant/machines';
import type { PlantModel } from '../plant/types';
import { UsageError } from './io';

function describe(m: PlantModel, withTask: boolean): string {
  const out = [`${m.id}: ${m.title}`];
  if (withTask) out.push('', ...m.task.split('\n').map((l) => `  ${l}`), '');
  out.push('  I/O:');
  // Columns as wide as the longest name (and at least as wide as the tank's), a space apart.
  const nameWidth = Math.max(11, ...m.points.map((p) => p.name.length)) + 1;
  const quantityWidth = Math.max(19, ...m.quantities.map((q) => m.id.length + 1 + q.name.length)) + 1;
  for (const p of m.points)
    out.push(
      `    ${p.address.padEnd(8)}${p.name.padEnd(nameWidth)}${p.type.padEnd(6)}${(p.kind + (p.control ? ` (${p.control})` : '')).padEnd(19)}${p.comment}`,
    );
  out.push('  Faults:');
  const faultWidth = Math.max(19, ...m.faults.map((f) => f.id.length)) + 1;
  for (const f of m.faults) out.push(`    ${f.id.padEnd(faultWidth)}${f.title}`);
  out.push('  Quantities:');
  for (const q of m.quantities)
    out.push(
      `    ${`${m.id}.${q.name}`.padEnd(quantityWidth)}${q.type.padEnd(6)}${(q.unit ?? '').padEnd(5)}${q.comment}`,
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
