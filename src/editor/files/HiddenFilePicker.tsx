// The hidden <input type="file"> behind a menu command: it hands its "open the picker" function to
// the command's UI store while mounted, and passes on the file the user chose.
import { useEffect, useRef } from 'react';

export interface HiddenFilePickerProps {
  /** The input's accept list (".json,application/json"). */
  readonly accept: string;
  readonly label: string;
  readonly testId: string;
  /** Receives the function that opens the browser's file picker (undefined once unmounted). */
  readonly register: (open: (() => void) | undefined) => void;
  readonly onFile: (file: File) => void;
}

export function HiddenFilePicker({ accept, label, testId, register, onFile }: HiddenFilePickerProps) {
  const input = useRef<HTMLInputElement>(null);
  useEffect(() => {
    register(() => input.current?.click());
    return () => register(undefined);
  }, [register]);
  return (
    <input
      ref={input}
      type="file"
      accept={accept}
      hidden
      data-testid={testId}
      aria-label={label}
      onChange={(e) => {
        const file = e.target.files?.[0];
        e.target.value = ''; // choosing the same file again still fires
        if (file) onFile(file);
      }}
    />
  );
}
