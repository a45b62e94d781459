// Mounted once: the paste prompt (keep or renew the FB instances of pasted networks) and the
// Ctrl+G "go to network" box.
import { useMemo, useState } from 'react';
import { selectNetworks, useDocument, useDocumentStore } from '../../store/documentStore';
import { useUi, useUiStore } from '../../store/uiStore';
import type { EditorContext } from '../commands/editorActions';
import { pasteNetworksText } from '../commands/networkActions';
import { useModal } from '../layout/useModal';
import { goToNetwork } from './goTo';
import './outline.css';

function PastePrompt({ ctx }: { readonly ctx: EditorContext }) {
  const prompt = useUi((s) => s.pastePrompt);
  if (!prompt) return null;
  return <PasteQuestion ctx={ctx} instances={prompt.instances} text={prompt.text} />;
}

function PasteQuestion({ ctx, instances, text }: { readonly ctx: EditorContext; readonly instances: readonly string[]; readonly text: string }) {
  const cancel = () => ctx.ui.getState().setPastePrompt(undefined);
  const modal = useModal(cancel);
  return (
    <div className="rs-floating" role="dialog" aria-modal="true" aria-label="Paste networks" data-testid="paste-prompt" {...modal}>
      <div>
        The pasted networks call FB instances this POU already has:{' '}
        <strong className="rs-mono">{instances.join(', ')}</strong>
      </div>
      <div className="rs-row">
        <button
          type="button"
          autoFocus
          data-testid="paste-new-instances"
          title="Each instance gets the next free name (Timer1 → Timer2), declared with the same type"
          onClick={() => pasteNetworksText(ctx, text, 'new')}
        >
          New instances
        </button>
        <button
          type="button"
          data-testid="paste-keep-instances"
          title="Call the same instances again (legal IEC; the checks warn, LD-R10)"
          onClick={() => pasteNetworksText(ctx, text, 'keep')}
        >
          Keep instances
        </button>
        <button type="button" onClick={cancel}>
          Cancel
        </button>
      </div>
    </div>
  );
}

function GoToBox({ ctx }: { readonly ctx: EditorContext }) {
  const mode = useUi((s) => s.finder);
  const open = mode === 'goto' || mode === 'gotoExtend';
  const extend = mode === 'gotoExtend';
  const count = useDocument(selectNetworks).length;
  const [text, setText] = useState('');
  const [error, setError] = useState('');
  if (!open) return null;
  const close = () => {
    setText('');
    setError('');
    ctx.ui.getState().setFinder(undefined);
  };
  const go = () => {
    const problem = goToNetwork(ctx, text, extend);
    if (problem) setError(problem);
    else close();
  };
  return (
    <div
      className="rs-floating"
      role="dialog"
      aria-label={extend ? 'Extend selection to network' : 'Go to network'}
      data-testid="goto-box"
      data-extend={extend || undefined}
    >
      <label>
        {extend ? 'Extend the selection to network' : 'Go to network'} (1–{count}) or label
        <input
          autoFocus
          data-testid="goto-input"
          value={text}
          onChange={(e) => setText(e.target.value)}
          onKeyDown={(e) => {
            e.stopPropagation();
            if (e.key === 'Enter') go();
            if (e.key === 'Escape') close();
          }}
        />
      </label>
      {error && (
        <div className="rs-row" role="alert">
          {error}
        </div>
      )}
    </div>
  );
}

export function NetworkUnitsHost() {
  const doc = useDocumentStore();
  const ui = useUiStore();
  const ctx = useMemo<EditorContext>(() => ({ doc, ui }), [doc, ui]);
  return (
    <>
      <PastePrompt ctx={ctx} />
      <GoToBox ctx={ctx} />
    </>
  );
}
