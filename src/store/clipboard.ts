// Copy/paste payload: JSON text with a `rungsmith-clip` marker, so it survives the system
// clipboard (and pasting between browser tabs). Parsing validates it like a project file.
import { newNetwork, newProject } from '../model/factory';
import type { VLink } from '../model/elements';
import { validateProject } from '../model/load';
import type { Variable } from '../model/project';
import type { ClipContent } from './networkEdits';

export const CLIP_FORMAT = 'rungsmith-clip';
export const CLIP_VERSION = 1;

export interface Clip extends ClipContent {
  readonly format: typeof CLIP_FORMAT;
  readonly version: typeof CLIP_VERSION;
  /** Declarations of the variables the copied elements use, for pasting into another project. */
  readonly variables: readonly Variable[];
}

export const clipText = (content: ClipContent, variables: readonly Variable[] = []): string =>
  JSON.stringify({
    format: CLIP_FORMAT,
    version: CLIP_VERSION,
    elements: content.elements,
    vlinks: content.vlinks,
    variables,
  } satisfies Clip);

/** The JSON object in `text` (a clip read from the system clipboard), or undefined. */
export function jsonObject(text: string): Record<string, unknown> | undefined {
  let data: unknown;
  try {
    data = JSON.parse(text);
  } catch {
    return undefined;
  }
  return typeof data === 'object' && data !== null ? (data as Record<string, unknown>) : undefined;
}

/** The clip in `text`, or undefined when the text is not a valid Rungsmith clip. */
export function parseClip(text: string): Clip | undefined {
  const d = jsonObject(text);
  if (!d) return undefined;
  if (
    d.format !== CLIP_FORMAT ||
    d.version !== CLIP_VERSION ||
    !Array.isArray(d.elements) ||
    !Array.isArray(d.vlinks)
  )
    return undefined;
  // Validate the elements and declarations by loading them as a one-network project.
  const probe = newProject('clip');
  const pou = probe.pous[0]!;
  const vlinks = d.vlinks as VLink[];
  const rows =
    1 +
    Math.max(
      0,
      ...(d.elements as { row?: number }[]).map((e) => (e.row ?? 0) + 16),
      ...vlinks.map((v) => (v.row ?? 0) + 2),
    );
  const cols =
    1 +
    Math.max(
      0,
      ...(d.elements as { col?: number }[]).map((e) => (e.col ?? 0) + 2),
      ...vlinks.map((v) => v.boundary ?? 0),
    );
  const net = { ...newNetwork(), rows, cols, elements: d.elements, vlinks: d.vlinks };
  const variables = Array.isArray(d.variables) ? d.variables : [];
  const result = validateProject({ ...probe, pous: [{ ...pou, variables, networks: [net] }] });
  if (!result.ok) return undefined;
  const loaded = result.project.pous[0]!;
  const n = loaded.networks[0]!;
  return {
    format: CLIP_FORMAT,
    version: CLIP_VERSION,
    elements: n.elements,
    vlinks: n.vlinks,
    variables: loaded.variables,
  };
}
