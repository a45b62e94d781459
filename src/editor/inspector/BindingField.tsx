// A labelled name field of the inspector: completion while typing, what the name is once bound,
// and the "declare it?" offer when it is not declared.
import { useId } from 'react';
import { findVariable } from '../../model/factory';
import { selectActivePou, selectProject, useDocument, useDocumentStore } from '../../store/documentStore';
import { declareChoice, declareChoices } from './declareOffer';
import { acceptedTypes, describeLiteral, resolveName, type BindingRole } from './operands';
import { VariableInput } from './VariableInput';

interface Props {
  readonly label: string;
  /** Shown under the label, on a line of its own (a pin's type: `ANY_MAGNITUDE` is wider than the label column). */
  readonly detail?: string;
  readonly value: string;
  readonly role: BindingRole;
  readonly onCommit: (text: string) => void;
  readonly placeholder?: string;
  readonly testId?: string;
  /** What the field binds (VariableInput's resetKey). */
  readonly resetKey?: string;
}

export function BindingField({ label, detail, value, role, onCommit, placeholder, testId, resetKey }: Props) {
  const id = useId();
  return (
    <div className="rs-field">
      <label htmlFor={id} title={detail ? `${label} : ${detail}` : undefined}>
        {label}
        {detail ? <span className="rs-field-detail">{detail}</span> : null}
      </label>
      <div>
        <VariableInput
          id={id}
          value={value}
          role={role}
          onCommit={onCommit}
          aria-label={detail ? `${label} : ${detail}` : label}
          placeholder={placeholder}
          data-testid={testId}
          resetKey={resetKey}
        />
      </div>
      <BindingInfo value={value} role={role} />
    </div>
  );
}

function BindingInfo({ value, role }: { value: string; role: BindingRole }) {
  const store = useDocumentStore();
  const project = useDocument(selectProject);
  const pou = useDocument(selectActivePou);
  if (!pou || value.trim() === '') return null;
  if (role.kind === 'pin' && role.direction === 'input') {
    const literal = describeLiteral(value.trim(), role.pinType);
    if (literal)
      return <p className={`rs-binding-info${literal.ok ? '' : ' rs-error-text'}`}>{literal.text}</p>;
  }
  const resolution = resolveName(project, pou, value);
  switch (resolution.status) {
    case 'empty':
      return null;
    case 'other':
      return <p className="rs-binding-info rs-error-text">{resolution.message}</p>;
    case 'declared': {
      const accepted = acceptedTypes(role);
      const v = findVariable(project, pou, value.trim());
      const details = [resolution.type, v?.location, v?.comment]
        .filter((s) => s && s.trim() !== '')
        .join(' · ');
      const fits = accepted.includes(resolution.type);
      return (
        <p className={fits ? 'rs-binding-info' : 'rs-binding-info rs-warning-text'}>
          {fits
            ? details
            : `${value.trim()} is ${resolution.type}; this needs ${accepted.length > 4 ? 'another type' : accepted.join(' or ')}`}
        </p>
      );
    }
    case 'undeclared': {
      const choices = declareChoices(project, resolution.name, role, pou);
      return (
        <div
          className="rs-declare-offer"
          role="group"
          aria-label={`Declare ${resolution.name}`}
          data-testid="declare-offer"
        >
          <p>
            <strong>{resolution.name}</strong> is not declared. Declare it as
          </p>
          {choices.map((choice) => (
            <button
              key={choice.label}
              type="button"
              className="rs-button"
              onClick={() => declareChoice(store.getState(), choice, pou.id)}
            >
              {choice.label}
            </button>
          ))}
          {choices.length === 0 && (
            <p className="rs-error-text">"{resolution.name}" cannot be a variable name.</p>
          )}
        </div>
      );
    }
  }
}
