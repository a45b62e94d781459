// Free IEC addresses, so "declare it as an input" can pick the next unused %IX bit or %IW word.
import { locationText, parseLocation } from '../../model/iecTypes';
import type { Project } from '../../model/project';
import { mappedPoints } from '../../plant/loop';
import { plantById } from '../../plant/machines';
import type { PlantPoint } from '../../plant/types';
import { addressOwners } from './validation';

/** The project's machine's points at their addresses as the project wires them (none without a machine). */
export function machinePoints(project: Pick<Project, 'plant'>): PlantPoint[] {
  const model = project.plant ? plantById(project.plant.id) : undefined;
  return model ? mappedPoints(model, project.plant?.map ?? {}) : [];
}

const canonicalAddress = (address: string): string | undefined => {
  const loc = parseLocation(address);
  return loc ? locationText(loc) : undefined;
};

export type AddressArea = 'I' | 'Q' | 'M';

/** The size letter an elementary type needs: BOOL -> X, 16-bit -> W, and so on. */
export function sizeForType(type: string): 'X' | 'B' | 'W' | 'D' | 'L' | undefined {
  switch (type.toUpperCase()) {
    case 'BOOL':
      return 'X';
    case 'BYTE':
    case 'SINT':
    case 'USINT':
      return 'B';
    case 'WORD':
    case 'INT':
    case 'UINT':
      return 'W';
    case 'DWORD':
    case 'DINT':
    case 'UDINT':
    case 'REAL':
    case 'TIME':
      return 'D';
    case 'LWORD':
    case 'LINT':
    case 'ULINT':
    case 'LREAL':
      return 'L';
    default:
      return undefined;
  }
}

/**
 * The first address of `area` able to hold `type` that no variable of the project uses and no point
 * of its machine is wired to (the machine writes its inputs every scan and reads its outputs: a new
 * input there would read the machine's Start button, a new output drive its pump):
 * bits run %IX0.0 .. %IX0.7, %IX1.0 ...; words %IW0, %IW1 ... Undefined for FB types.
 */
export function nextFreeAddress(project: Project, area: AddressArea, type: string): string | undefined {
  const size = sizeForType(type);
  if (!size) return undefined;
  const used = new Set<string>();
  for (const key of [
    ...addressOwners(project).keys(),
    ...machinePoints(project).map((p) => canonicalAddress(p.address) ?? ''),
  ]) {
    const loc = parseLocation(key);
    if (loc && loc.area === area && loc.size === size) used.add(locationText(loc));
  }
  for (let index = 0; index < 100_000; index++) {
    if (size === 'X') {
      for (let bit = 0; bit < 8; bit++) {
        const candidate = `%${area}X${index}.${bit}`;
        if (!used.has(candidate)) return candidate;
      }
    } else {
      const candidate = `%${area}${size}${index}`;
      if (!used.has(candidate)) return candidate;
    }
  }
  return undefined;
}
