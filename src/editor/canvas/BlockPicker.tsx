// The searchable block picker (key B): the project's own FBs and functions, then every standard
// function block and library function, each with its pins.
// Type to filter, arrows to choose, Enter to place the box at the cursor.
import { useMemo, useState } from 'react';
import { selectActivePou, selectLibrary, useDocument, useDocumentStore } from '../../store/documentStore';
import { useUi, useUiStore } from '../../store/uiStore';
import { placeAt } from '../commands/editorActions';
import { boxTemplate, pinSummary, searchBlocks } from '../palette/paletteItems';

export function BlockPicker({ onDone }: { readonly onDone: () => void }) {
  const doc = useDocumentStore();
  const ui = useUiStore();
  const picker = useUi((s) => s.blockPicker);
  const [query, setQuery] = useState('');
  const [active, setActive] = useState(0);
  const library = useDocument(selectLibrary);
  // The edited POU's name and kind only (what searchBlocks reads); nothing searched while closed.
  const editingName = useDocument((s) => selectActivePou(s)?.name);
  const editingKind = useDocument((s) => selectActivePou(s)?.kind);
  const results = useMemo(
    () =>
      picker
        ? searchBlocks(
            query,
            library,
            editingName !== undefined && editingKind ? { name: editingName, kind: editingKind } : undefined,
          ).slice(0, 200)
        : [],
    [picker, query, library, editingName, editingKind],
  );
  if (!picker) return null;
  const index = Math.min(active, results.length - 1);

  const close = () => {
    ui.getState().closeBlockPicker();
    setQuery('');
    setActive(0);
    onDone();
  };
  const choose = (i: number) => {
    const sig = results[i];
    if (!sig) return;
    ui.getState().closeBlockPicker();
    setQuery('');
    setActive(0);
    placeAt({ doc, ui }, picker.network, picker.cell, boxTemplate(sig, library));
    if (!ui.getState().editing) onDone();
  };

  return (
    <div className="rs-block-picker" role="dialog" aria-label="Choose a block" data-testid="block-picker">
      <input
        autoFocus
        role="combobox"
        aria-expanded
        aria-controls="rs-block-picker-list"
        aria-activedescendant={results[index] ? `rs-block-${results[index].name}` : undefined}
        aria-label="Search blocks"
        placeholder="Search blocks: TON, ADD, INT_TO_REAL…"
        value={query}
        onChange={(e) => {
          setQuery(e.target.value);
          setActive(0);
        }}
        onKeyDown={(e) => {
          e.stopPropagation();
          if (e.key === 'ArrowDown' || e.key === 'ArrowUp') {
            e.preventDefault();
            const step = e.key === 'ArrowDown' ? 1 : -1;
            setActive((index + step + results.length) % Math.max(1, results.length));
          } else if (e.key === 'Enter') {
            e.preventDefault();
            choose(index);
          } else if (e.key === 'Escape') {
            e.preventDefault();
            close();
          }
        }}
        onBlur={close}
      />
      <ul id="rs-block-picker-list" role="listbox" aria-label="Blocks">
        {results.map((sig, i) => (
          <li
            key={sig.name}
            id={`rs-block-${sig.name}`}
            role="option"
            aria-selected={i === index}
            onMouseDown={(e) => e.preventDefault()}
            onMouseEnter={() => setActive(i)}
            onClick={() => choose(i)}
          >
            <span className="rs-mono rs-block-name">{sig.name}</span>
            <span className="rs-block-kind">
              {sig.library ? `${sig.library} ` : sig.category === 'user' ? 'user ' : ''}
              {sig.kind === 'fb' ? 'FB' : 'function'}
            </span>
            <span className="rs-block-desc" title={pinSummary(sig)}>
              {sig.category === 'user' ? pinSummary(sig) : sig.description}
            </span>
          </li>
        ))}
        {results.length === 0 && <li className="rs-empty">No block matches “{query}”.</li>}
      </ul>
    </div>
  );
}
