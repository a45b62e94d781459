// A name field with completion from the variable table (an ARIA combobox). Typing an undeclared
// name offers to declare it right in the list ("Declare Motor : BOOL output at %QX0.0"); choosing
// that declares the variable and binds it as one undo step. Global offers ("Declare Motor : BOOL
// global") go to the project's globals (with a VAR_EXTERNAL in the POU where it needs one). Enter takes the highlighted offer;
// Shift+Enter keeps the text exactly as typed; one Escape leaves the field unchanged.
//
// Used by the inspector and by the canvas's inline editor:
//   <VariableInput value={el.variable} role={{ kind: 'contact' }} onCommit={(name) => ...} onCancel={...} autoFocus />
// onCommit gets the final text (trimmed); it is called inside a document batch when a declaration
// was chosen, so the caller's own edit joins the same undo step.
import { useId, useMemo, useRef, useState, type KeyboardEvent } from 'react';
import { parseLiteral } from '../../engine/values/literals';
import { selectActivePou, selectProject, useDocument, useDocumentStore } from '../../store/documentStore';
import { focusCanvas } from '../canvas/focusCanvas';
import { declareChoice, declareChoices, machinePointOffers, typedDeclaration, type DeclareChoice } from './declareOffer';
import { blockLibrary } from '../../model/library';
import { freshInstanceName } from '../../store/pouEdits';
import { candidatesFor, rankCandidates, resolveName, type BindingRole, type Candidate } from './operands';
import './inspector.css';

export interface VariableInputProps {
  readonly value: string;
  readonly role: BindingRole;
  /** `how`: the key that committed (Enter, or Tab / Shift+Tab with `tabMoves`); undefined on leaving the field. */
  readonly onCommit: (text: string, how?: EndKey) => void;
  /**
   * The field closes without a change: Escape ('escape': one press, also with the list open; the
   * keyboard goes back to the canvas when the caller does not take it), Enter (or Tab with
   * `tabMoves`) on the unchanged text (the caller may move on as after a commit), or leaving the
   * field when commitOnBlur is false ('blur').
   */
  readonly onCancel?: (how: CancelReason) => void;
  /** Tab / Shift+Tab end the edit like Enter and report 'tab' / 'backtab' (the caller moves on). */
  readonly tabMoves?: boolean;
  /** Leaving the field commits the text (inspector); false: leaving cancels (inline editor). Default true. */
  readonly commitOnBlur?: boolean;
  readonly autoFocus?: boolean;
  /** id of the text field, for a <label htmlFor>. */
  readonly id?: string;
  readonly placeholder?: string;
  readonly 'aria-label'?: string;
  readonly 'data-testid'?: string;
  readonly className?: string;
  /**
   * What the field binds (the inspector's element): a field kept for the next element of the same
   * kind drops what was typed for the previous one and closes its list.
   */
  readonly resetKey?: string;
}

export type EndKey = 'enter' | 'tab' | 'backtab';
export type CancelReason = EndKey | 'escape' | 'blur';

type Option =
  | { readonly kind: 'candidate'; readonly candidate: Candidate }
  | { readonly kind: 'declare'; readonly choice: DeclareChoice };

/** Input pins accept literals (`T#5s`, `10`), which need no completion and no declaration. */
const NO_CANDIDATES: readonly Candidate[] = [];
const NO_OPTIONS: Option[] = [];

const isLiteralFor = (role: BindingRole, text: string) =>
  role.kind === 'pin' && role.direction === 'input' && parseLiteral(text.trim()).ok;

export function VariableInput(props: VariableInputProps) {
  const { value, role, onCommit, onCancel, commitOnBlur = true } = props;
  const store = useDocumentStore();
  const project = useDocument(selectProject);
  const pou = useDocument(selectActivePou);
  const listId = useId();
  const [draft, setDraft] = useState<string | undefined>(undefined);
  const [open, setOpen] = useState(false);
  const [active, setActive] = useState(0);
  /** Set while Escape moves the focus away: that blur must not commit. */
  const escaping = useRef(false);
  /** The user moved in the list with the arrows (an untouched field's list is only a suggestion). */
  const navigated = useRef(false);
  const [draftFor, setDraftFor] = useState(props.resetKey);
  if (draftFor !== props.resetKey) {
    setDraftFor(props.resetKey);
    setDraft(undefined);
    setOpen(false);
    setActive(0);
  }
  const text = draft ?? value;

  // The names the field can offer depend on the declarations, not on what is typed: built once per
  // document version and role, then only ranked per keystroke (a POU of thousands of variables).
  // Only an open list needs them: a closed field (the inspector's, on every selection and edit)
  // builds nothing, and nothing reads them while it is closed (`shown` needs `open`).
  const roleKey = JSON.stringify(role);
  const candidates = useMemo(
    () => (pou && open ? candidatesFor(project, pou, role) : NO_CANDIDATES),
    // eslint-disable-next-line react-hooks/exhaustive-deps -- `role` is compared by value (callers build it per render)
    [project, pou, roleKey, open],
  );
  const options = useMemo<Option[]>(() => {
    if (!open || !pou || isLiteralFor(role, text)) return NO_OPTIONS;
    const ranked = rankCandidates(text, candidates).map((candidate) => ({
      kind: 'candidate' as const,
      candidate,
    }));
    // `Speed : INT`: declare Speed with the type written after the colon.
    const typed = role.kind === 'instance' ? undefined : typedDeclaration(project, text);
    const resolution = resolveName(project, pou, typed?.name ?? text);
    // An empty instance of the project's own FB: offer its next free name (Motor1, Motor2...).
    const offered =
      resolution.status === 'undeclared'
        ? (typed?.name ?? text)
        : resolution.status === 'empty' &&
            role.kind === 'instance' &&
            blockLibrary(project).userPou(role.blockType)
          ? freshInstanceName(project, pou, role.blockType)
          : undefined;
    const declares =
      offered !== undefined
        ? declareChoices(project, offered, role, pou, typed?.type).map((choice) => ({ kind: 'declare' as const, choice }))
        : [];
    // The offered fresh instance comes first: a second call needs a new instance, not Motor1 again.
    if (offered !== undefined && offered !== text) return [...declares, ...ranked];
    // A new name typed whole: names that only contain it (`Jam` in `ConveyorJam`) come after the offer
    // to declare it, so Enter never binds another variable than the one typed; names that start
    // with it stay first (the user may be completing one).
    const q = text.trim().toUpperCase();
    const starts = ranked.filter((o) => o.candidate.text.toUpperCase().startsWith(q));
    const contains = ranked.filter((o) => !o.candidate.text.toUpperCase().startsWith(q));
    // The machine's points that start with it (`Hi`: HighLevel), after the offer of the name typed.
    const machine = typed ? [] : machinePointOffers(project, text, role, pou).map((choice) => ({ kind: 'declare' as const, choice }));
    return [...starts, ...declares, ...machine, ...contains];
    // eslint-disable-next-line react-hooks/exhaustive-deps -- `role` is compared by value (callers build it per render)
  }, [project, pou, roleKey, candidates, text, open]);
  const shown = open && options.length > 0;
  const activeIndex = Math.min(active, options.length - 1);

  /** Commits a changed text; an unchanged one ends the edit as `unchanged` says (undefined: silently). */
  const finish = (final: string, how?: EndKey) => {
    navigated.current = false;
    setDraft(undefined);
    setOpen(false);
    setActive(0);
    if (final.trim() !== value.trim()) onCommit(final.trim(), how);
    else if (how) onCancel?.(how);
  };
  const choose = (option: Option, how: EndKey = 'enter') => {
    if (option.kind === 'candidate') return finish(option.candidate.text, how);
    const name = option.choice.variable.name;
    navigated.current = false;
    const pouId = pou?.id;
    if (!pouId) return;
    store.getState().batch('declareVariable', () => {
      declareChoice(store.getState(), option.choice, pouId);
      setDraft(undefined);
      setOpen(false);
      setActive(0);
      onCommit(name, how);
    });
  };

  const onKeyDown = (e: KeyboardEvent<HTMLInputElement>) => {
    e.stopPropagation(); // typing here never triggers canvas shortcuts
    if (e.key === 'ArrowDown' || e.key === 'ArrowUp') {
      e.preventDefault();
      if (!shown) return setOpen(true);
      navigated.current = true;
      const step = e.key === 'ArrowDown' ? 1 : -1;
      setActive((activeIndex + step + options.length) % options.length);
    } else if (e.key === 'Enter' || (e.key === 'Tab' && props.tabMoves)) {
      e.preventDefault();
      const how: EndKey = e.key === 'Enter' ? 'enter' : e.shiftKey ? 'backtab' : 'tab';
      // Shift+Enter keeps the text exactly as typed (an undeclared name), whatever the list offers.
      // On a field not typed in, only an offer to declare (a new instance) or an option the user
      // moved to is taken: Enter or Tab through an untouched pin leaves it empty.
      const offered = shown && !(e.key === 'Enter' && e.shiftKey) ? options[activeIndex] : undefined;
      const option =
        offered && (draft !== undefined || navigated.current || offered.kind === 'declare') ? offered : undefined;
      if (option) choose(option, how);
      else finish(text, how);
    } else if (e.key === 'Escape') {
      e.preventDefault();
      setDraft(undefined);
      setOpen(false);
      setActive(0);
      const field = e.currentTarget;
      onCancel?.('escape');
      if (document.activeElement === field) {
        escaping.current = true;
        focusCanvas(field);
        escaping.current = false;
      }
    } else if (e.key === 'Tab' && shown) {
      const option = options[activeIndex];
      if (option?.kind === 'candidate') {
        e.preventDefault();
        setDraft(option.candidate.text);
        setOpen(false);
      }
    }
  };

  return (
    <div className={`rs-varinput ${props.className ?? ''}`}>
      <input
        role="combobox"
        id={props.id}
        aria-label={props['aria-label'] ?? 'Variable'}
        aria-expanded={shown}
        aria-controls={listId}
        aria-autocomplete="list"
        aria-activedescendant={shown ? `${listId}-${activeIndex}` : undefined}
        data-testid={props['data-testid']}
        className="rs-cell-input rs-mono"
        autoFocus={props.autoFocus}
        spellCheck={false}
        autoComplete="off"
        placeholder={props.placeholder}
        value={text}
        onChange={(e) => {
          setDraft(e.target.value);
          setOpen(true);
          setActive(0);
        }}
        onFocus={() => setOpen(true)}
        onBlur={() => {
          if (escaping.current) return;
          if (commitOnBlur) finish(text);
          else {
            setDraft(undefined);
            setOpen(false);
            onCancel?.('blur');
          }
        }}
        onKeyDown={onKeyDown}
      />
      {shown && (
        <ul id={listId} role="listbox" className="rs-completions" aria-label="Suggestions">
          {options.map((option, i) => (
            <li
              key={option.kind === 'candidate' ? `c:${option.candidate.text}` : `d:${option.choice.label}`}
              id={`${listId}-${i}`}
              role="option"
              aria-selected={i === activeIndex}
              className={option.kind === 'declare' ? 'rs-completion rs-declare' : 'rs-completion'}
              onMouseDown={(e) => e.preventDefault()} // keep focus in the field
              onMouseEnter={() => setActive(i)}
              onClick={() => choose(option)}
            >
              {option.kind === 'candidate' ? (
                <>
                  <span className="rs-mono">{option.candidate.text}</span>
                  <span className="rs-completion-type">{option.candidate.type}</span>
                  <span className="rs-completion-detail">{option.candidate.detail}</span>
                </>
              ) : (
                <>
                  <span>
                    Declare <span className="rs-mono">{option.choice.variable.name}</span>
                  </span>
                  <span className="rs-completion-type">{option.choice.label}</span>
                </>
              )}
            </li>
          ))}
        </ul>
      )}
    </div>
  );
}
