// Text fields that edit a document value as one step: typing changes only a draft; Enter or
// leaving the field commits it (Shift+Enter is a new line in a multi-line field), Escape restores
// the document value and leaves the field, giving the keyboard back to the canvas.
import {
  useRef,
  useState,
  type InputHTMLAttributes,
  type KeyboardEvent,
  type TextareaHTMLAttributes,
} from 'react';
import { focusCanvas } from '../canvas/focusCanvas';

type Field = HTMLInputElement | HTMLTextAreaElement;

/**
 * Key events whose Enter committed a changed text: a container can tell "Enter confirmed an edit"
 * from "Enter on a field with nothing to commit" (the variable table adds a row on the latter).
 */
export const committedByEnter = new WeakSet<Event>();

export interface CommitOptions {
  /** Shift+Enter inserts a new line; Enter alone still commits. */
  readonly multiline?: boolean;
  /** Enter also leaves the field for the canvas (the network header's title and comment). */
  readonly leaveOnEnter?: boolean;
  /**
   * What the field edits (the inspector's element): a field kept for the next element of the same
   * kind (not built again on every selection) drops a draft typed for the previous one.
   */
  readonly resetKey?: string;
}

/** The value, change, key and blur handlers of a field that commits once (see the file comment). */
export function useCommitField<E extends Field>(
  value: string,
  onCommit: (text: string) => void,
  { multiline = false, leaveOnEnter = false, resetKey }: CommitOptions = {},
) {
  const [draft, setDraft] = useState<string | undefined>(undefined);
  const [draftFor, setDraftFor] = useState(resetKey);
  if (draftFor !== resetKey) {
    setDraftFor(resetKey);
    setDraft(undefined);
  }
  /** Set while Escape moves the focus away: that blur must not commit. */
  const reverting = useRef(false);
  const commit = () => {
    if (!reverting.current && draft !== undefined && draft !== value) onCommit(draft);
    setDraft(undefined);
  };
  return {
    value: draft ?? value,
    onChange: (e: { target: { value: string } }) => setDraft(e.target.value),
    onKeyDown: (e: KeyboardEvent<E>) => {
      if (e.key === 'Enter' && !(multiline && e.shiftKey)) {
        e.preventDefault();
        if (draft !== undefined && draft !== value) committedByEnter.add(e.nativeEvent);
        commit();
        if (leaveOnEnter) focusCanvas(e.currentTarget);
      } else if (e.key === 'Escape') {
        e.preventDefault();
        setDraft(undefined);
        reverting.current = true;
        focusCanvas(e.currentTarget);
        reverting.current = false;
      }
    },
    onBlur: commit,
  };
}

type InputProps = Omit<InputHTMLAttributes<HTMLInputElement>, 'value' | 'onChange' | 'defaultValue'> & {
  readonly value: string;
  readonly onCommit: (text: string) => void;
  /** See CommitOptions.resetKey. */
  readonly resetKey?: string;
};

export function CommitInput({ value, onCommit, onKeyDown, onBlur, resetKey, ...rest }: InputProps) {
  const field = useCommitField<HTMLInputElement>(value, onCommit, { resetKey });
  return (
    <input
      {...rest}
      value={field.value}
      onChange={field.onChange}
      onKeyDown={(e) => {
        onKeyDown?.(e);
        if (!e.defaultPrevented) field.onKeyDown(e);
      }}
      onBlur={(e) => {
        field.onBlur();
        onBlur?.(e);
      }}
    />
  );
}

type AreaProps = Omit<TextareaHTMLAttributes<HTMLTextAreaElement>, 'value' | 'onChange' | 'defaultValue'> & {
  readonly value: string;
  readonly onCommit: (text: string) => void;
  /** See CommitOptions.resetKey. */
  readonly resetKey?: string;
};

/** A multi-line CommitInput: Enter commits, Shift+Enter is a new line. */
export function CommitTextArea({ value, onCommit, resetKey, ...rest }: AreaProps) {
  const field = useCommitField<HTMLTextAreaElement>(value, onCommit, { multiline: true, resetKey });
  return <textarea {...rest} {...field} />;
}
