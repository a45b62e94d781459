// The palette: pick a tool, then click a cell on the canvas (or press the shortcut shown in each
// tooltip to place at the keyboard cursor). Blocks come from a searchable list of the project's
// own function blocks and functions, then every standard function block and library function.
import { useMemo, useState } from 'react';
import type { BlockSignature } from '../../model/blocks';
import { selectActivePou, selectLibrary, useDocument } from '../../store/documentStore';
import { useUi, useUiStore, type Tool } from '../../store/uiStore';
import type { EditorContext } from '../commands/editorActions';
import { keyLabel } from '../commands/keys';
import { commandById } from '../commands/registry';
import { boxTemplate, PALETTE_ITEMS, pinSummary, searchBlocks, type PaletteItem } from './paletteItems';
import './palette.css';

const GROUPS: readonly PaletteItem['group'][] = ['Contacts', 'Coils', 'Wires', 'Control'];

const shortcutText = (keys: string | undefined) => (keys ? ` (${keyLabel(keys)})` : '');

function isActive(tool: Tool, id: string): boolean {
  if (tool.kind !== 'place') return false;
  return tool.name === id;
}

export function Palette({ ctx }: { readonly ctx: EditorContext }) {
  const ui = useUiStore();
  const tool = useUi((s) => s.tool);
  const [query, setQuery] = useState('');
  const library = useDocument(selectLibrary);
  // The edited POU's name and kind only (what searchBlocks reads): an edit inside it neither
  // re-renders the palette nor searches the blocks again.
  const editingName = useDocument((s) => selectActivePou(s)?.name);
  const editingKind = useDocument((s) => selectActivePou(s)?.kind);
  const blocks = useMemo(
    () => searchBlocks(query, library, editingName !== undefined && editingKind ? { name: editingName, kind: editingKind } : undefined),
    [query, library, editingName, editingKind],
  );

  const arm = (name: string, t: Tool) => {
    const current = ui.getState().tool;
    // Clicking the active tool again returns to selecting.
    ui.getState().setTool(current.kind === 'place' && current.name === name ? { kind: 'select' } : t);
  };
  const armBlock = (sig: BlockSignature) =>
    arm(`block-${sig.name}`, {
      kind: 'place',
      name: `block-${sig.name}`,
      template: boxTemplate(sig, library),
    });
  const runCommand = (id: string) => commandById(id)?.run(ctx);

  return (
    <nav className="rs-palette" aria-label="Palette" data-testid="palette">
      <div className="rs-palette-group" role="group" aria-label="Tools">
        <PaletteButton
          id="select"
          pressed={tool.kind === 'select'}
          title="Select and move (Esc): click, Shift+click, drag a rubber band, drag to move"
          symbol="↖"
          label="Select"
          onClick={() => ui.getState().setTool({ kind: 'select' })}
        />
        <PaletteButton
          id="vlink"
          pressed={tool.kind === 'vlink'}
          title="Vertical link tool: click between two rows on a cell edge to add or remove a vertical link (at the cursor: V left edge, Shift+V right edge)"
          symbol="┃"
          label="Vertical link"
          onClick={() =>
            ui.getState().setTool(tool.kind === 'vlink' ? { kind: 'select' } : { kind: 'vlink' })
          }
        />
      </div>
      {GROUPS.map((group) => (
        <div key={group} className="rs-palette-group" role="group" aria-label={group}>
          <h2 className="rs-palette-heading">{group}</h2>
          {PALETTE_ITEMS.filter((item) => item.group === group).map((item) => (
            <PaletteButton
              key={item.id}
              id={item.id}
              pressed={isActive(tool, item.id)}
              named
              title={`${item.label}${shortcutText(item.keys)}: ${item.description}`}
              symbol={item.symbol}
              mono
              label={item.label}
              onClick={() => arm(item.id, { kind: 'place', name: item.id, template: item.template })}
            />
          ))}
        </div>
      ))}
      <div className="rs-palette-group" role="group" aria-label="Network">
        <h2 className="rs-palette-heading">Network</h2>
        {NETWORK_TOOLS.map((t) => (
          <PaletteButton
            key={t.id}
            id={t.id}
            title={t.title}
            symbol={t.symbol}
            mono={t.mono}
            label={t.label}
            onClick={() => runCommand(t.command)}
          />
        ))}
      </div>
      <div className="rs-palette-group rs-palette-blocks" role="group" aria-label="Blocks">
        <h2 className="rs-palette-heading">Blocks</h2>
        <input
          type="search"
          className="rs-palette-search"
          aria-label="Search blocks"
          placeholder="Search: TON, ADD, INT_TO…"
          title="Filter function blocks and functions (B opens the block picker at the cursor)"
          value={query}
          onChange={(e) => setQuery(e.target.value)}
          onKeyDown={(e) => {
            e.stopPropagation();
            if (e.key === 'Enter' && blocks[0]) armBlock(blocks[0]);
          }}
        />
        <ul className="rs-palette-block-list" aria-label="Blocks">
          {blocks.filter((sig) => !sig.library).map((sig) => (
            <BlockItem key={sig.name} sig={sig} pressed={isActive(tool, `block-${sig.name}`)} onClick={() => armBlock(sig)} />
          ))}
        </ul>
      </div>
      {libraryGroups(blocks).map(([name, sigs]) => (
        <div key={name} className="rs-palette-group rs-palette-blocks rs-palette-library" role="group" aria-label={`Library ${name}`} data-testid={`palette-library-${name}`}>
          <h2 className="rs-palette-heading" title={`Blocks of the library ${name} (File > Libraries…)`}>
            {name}
          </h2>
          <ul className="rs-palette-block-list" aria-label={`Blocks of ${name}`}>
            {sigs.map((sig) => (
              <BlockItem key={sig.name} sig={sig} pressed={isActive(tool, `block-${sig.name}`)} onClick={() => armBlock(sig)} />
            ))}
          </ul>
        </div>
      ))}
    </nav>
  );
}

/** The blocks of each library kept with the project, by library, in the order found. */
function libraryGroups(blocks: readonly BlockSignature[]): [string, BlockSignature[]][] {
  const groups = new Map<string, BlockSignature[]>();
  for (const sig of blocks) if (sig.library) groups.set(sig.library, [...(groups.get(sig.library) ?? []), sig]);
  return [...groups];
}

/** A block of the list: arms the block tool. */
function BlockItem({ sig, pressed, onClick }: { readonly sig: BlockSignature; readonly pressed: boolean; readonly onClick: () => void }) {
  const owner = sig.library ? `library ${sig.library} ` : sig.category === 'user' ? 'this project’s ' : '';
  return (
    <li>
      <button
        type="button"
        className="rs-palette-item rs-palette-block"
        aria-pressed={pressed}
        data-testid={`palette-block-${sig.name}`}
        title={`${sig.name} (${owner}${sig.kind === 'fb' ? 'function block' : 'function'}): ${sig.description}\nPins: ${pinSummary(sig)}\nB opens the picker at the cursor`}
        onClick={onClick}
      >
        <span className="rs-mono">{sig.name}</span>
        <span className="rs-palette-kind">
          {sig.category === 'user' && !sig.library ? 'user ' : ''}
          {sig.kind === 'fb' ? 'FB' : 'fn'}
        </span>
      </button>
    </li>
  );
}

/** The Network group: each button runs an editor command on the cursor's network. */
const NETWORK_TOOLS = [
  {
    id: 'label',
    command: 'network.label',
    title: "Label of the cursor's network, a jump target (L)",
    symbol: 'L:',
    mono: true,
    label: 'Label',
  },
  {
    id: 'comment',
    command: 'network.comment',
    title: "Comment above the cursor's network (K)",
    symbol: '“ ”',
    mono: false,
    label: 'Comment',
  },
  {
    id: 'network',
    command: 'network.insert',
    title: "Insert a network below the cursor's network (N)",
    symbol: '＋',
    mono: false,
    label: 'New network',
  },
] as const;

interface PaletteButtonProps {
  /** Test id suffix: "palette-<id>". */
  readonly id: string;
  /** Whether the tool is armed; omitted for buttons that act at once. */
  readonly pressed?: boolean;
  /** Give the button its label as accessible name (the symbol is read otherwise). */
  readonly named?: boolean;
  readonly title: string;
  readonly symbol: string;
  /** Draw the symbol in the monospace font (IEC text symbols like -| |-). */
  readonly mono?: boolean;
  readonly label: string;
  readonly onClick: () => void;
}

function PaletteButton(p: PaletteButtonProps) {
  return (
    <button
      type="button"
      className="rs-palette-item"
      aria-pressed={p.pressed}
      aria-label={p.named ? p.label : undefined}
      data-testid={`palette-${p.id}`}
      title={p.title}
      onClick={p.onClick}
    >
      <span className={p.mono ? 'rs-palette-symbol rs-mono' : 'rs-palette-symbol'}>{p.symbol}</span>
      <span>{p.label}</span>
    </button>
  );
}
