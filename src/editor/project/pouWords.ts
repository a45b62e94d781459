// Words and icons for POU kinds, shared by the project tree and the POU tabs.
import type { PouKind } from '../../model/project';

export const KIND_ICONS: Record<PouKind, string> = { PROGRAM: 'P', FUNCTION_BLOCK: 'FB', FUNCTION: 'F' };

export const KIND_TITLES: Record<PouKind, string> = {
  PROGRAM: 'Program',
  FUNCTION_BLOCK: 'Function block',
  FUNCTION: 'Function',
};
