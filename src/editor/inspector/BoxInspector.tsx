// A function or function block box: instance, number of inputs, and the operand of every pin
// (a variable, `Instance.Pin`, or a literal such as T#5s).
import { boxLayout } from '../../model/boxLayout';
import type { BoxElement } from '../../model/elements';
import { declaredPinType } from '../../model/library';
import { selectLibrary, useDocument, useDocumentStore } from '../../store/documentStore';
import { BindingField } from './BindingField';
import { pinRole } from './operands';
import { CommitInput } from '../variables/CommitInput';
import { withOperand } from '../canvas/pinOperands';

export function BoxInspector({ box }: { box: BoxElement }) {
  const store = useDocumentStore();
  const library = useDocument(selectLibrary);
  const signature = library.signature(box.blockType);
  const layout = boxLayout(box, library);
  if (!signature || !layout) {
    return (
      <p className="rs-error-text">
        "{box.blockType}" is neither a standard block nor a function block or function of this project; add a
        POU of that name, or delete the box.
      </p>
    );
  }
  const update = store.getState().updateElement;
  const isFb = signature.kind === 'fb';
  const enEno = !isFb || box.executionControl === true;
  const powerIn = enEno ? 'EN' : layout.inputs.find((p) => p.type === 'BOOL')?.name;
  const powerOut = enEno ? 'ENO' : layout.outputs.find((p) => p.type === 'BOOL')?.name;
  const ext = signature.extensible;
  const callee = library.userPou(box.blockType);
  return (
    <>
      <p className="rs-inspector-where">{signature.description}</p>
      {box.executionOrder ? (
        <p
          className="rs-inspector-where"
          data-testid="box-execution-order"
          title="PLCopen executionOrderId from the imported file: under the openplc profile this block runs before every coil of the POU, in this order"
        >
          Execution order {box.executionOrder} (from the imported file)
        </p>
      ) : null}
      {callee && (
        <button
          type="button"
          className="rs-button"
          data-testid="open-callee"
          title={`Open ${callee.name} in a tab`}
          onClick={() => store.getState().setActivePou(callee.id)}
        >
          Open {callee.name}
        </button>
      )}
      {isFb && (
        <label
          className="rs-field"
          title="EN/ENO pins: with EN FALSE the instance is not called and keeps its outputs"
        >
          <span>EN/ENO</span>
          <input
            type="checkbox"
            data-testid="box-execution-control"
            checked={box.executionControl === true}
            onChange={(e) => update(box.id, { executionControl: e.target.checked || undefined })}
          />
        </label>
      )}
      {isFb && (
        <BindingField
          label="Instance"
          value={box.instance ?? ''}
          role={{ kind: 'instance', blockType: signature.name }}
          placeholder={`e.g. ${signature.name === 'TON' ? 'T1' : `${signature.name}_1`}`}
          testId="inspector-instance"
          onCommit={(instance) => update(box.id, { instance })}
        />
      )}
      {ext && (
        <div className="rs-field">
          <label htmlFor={`inputs-${box.id}`}>Inputs</label>
          <CommitInput
            id={`inputs-${box.id}`}
            type="number"
            min={ext.min}
            max={ext.max}
            className="rs-cell-input"
            value={String(
              layout.inputs.filter(
                (p) => p.name.startsWith(ext.prefix) && /^\d+$/.test(p.name.slice(ext.prefix.length)),
              ).length,
            )}
            onCommit={(text) => {
              const n = Math.round(Number(text));
              if (Number.isFinite(n)) update(box.id, { inputCount: Math.max(ext.min, Math.min(ext.max, n)) });
            }}
          />
        </div>
      )}
      <h3>Inputs</h3>
      {layout.inputs
        .filter((pin) => pin.name !== 'EN')
        .map((pin) => (
          <BindingField
            key={pin.name}
            label={pin.name}
            detail={declaredPinType(pin)}
            value={box.inputs[pin.name] ?? ''}
            role={pinRole(pin, 'input')}
            placeholder={pin.name === powerIn ? 'power flow from the left' : 'variable or literal'}
            testId={`pin-${pin.name}`}
            onCommit={(text) => update(box.id, { inputs: withOperand(box.inputs, pin.name, text) })}
          />
        ))}
      <h3>Outputs</h3>
      {layout.outputs
        .filter((pin) => pin.name !== 'ENO')
        .map((pin) => (
          <BindingField
            key={pin.name}
            label={pin.name}
            detail={declaredPinType(pin)}
            value={box.outputs[pin.name] ?? ''}
            role={pinRole(pin, 'output')}
            placeholder={pin.name === powerOut ? 'power flow to the right' : 'assign to a variable'}
            testId={`pin-${pin.name}`}
            onCommit={(text) => update(box.id, { outputs: withOperand(box.outputs, pin.name, text) })}
          />
        ))}
    </>
  );
}
