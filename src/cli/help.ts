// Help texts of the `rungsmith` command.
export const HELP = {
  main: `Usage: rungsmith <command> [options] FILE

Commands:
  check FILE                 check a project (.json) or PLCopen XML (.xml) against the LD rules
  simulate FILE [options]    run scans on a virtual clock and print a CSV trace
  export FILE.json -o OUT.xml    write a project as PLCopen TC6 XML v2.01
  import FILE.xml -o OUT.json    read PLCopen XML into a Rungsmith project
  test FILE [--junit OUT.xml]    run the project's test scenarios; exit 1 on any failure
  plants [NAME]              list the machines to control, their I/O maps, faults and quantities

Run "rungsmith <command> --help" for the options of a command.
Exit codes: 0 ok, 1 the program has errors, 2 bad usage or unreadable input.`,
  check: `Usage: rungsmith check FILE

Checks every POU of FILE (a .json project or a PLCopen .xml file) and prints one line per
diagnostic:  SEVERITY RULE-ID pou/network:cell message
(in an ST or IL body:  SEVERITY RULE-ID pou/line L col C message)
Exits with 1 if there is any error, 0 otherwise (warnings alone exit 0).`,
  simulate: `Usage: rungsmith simulate FILE [--pou NAME] [--inputs STIM.csv] [--scans N] [--cycle 10ms]
                          [--watch a,b,T1.Q] [--profile iec|openplc] [--plant NAME]

Runs N scans of a PROGRAM on the virtual clock and writes CSV to stdout:
  scan,time_ms,<watched...>   one row per scan after it ran; scan k starts at (k-1) x cycle.
  BOOL as 0/1, integers in decimal, REAL with enough digits to read back, TIME in ms.

Options:
  --pou NAME        the PROGRAM to run (default: the first one run by a task; when the tasks run
                    several program instances, all of them, each task at its own interval: a scan
                    is one tick of the gcd of the intervals, instances in declaration order)
  --inputs FILE     stimulus CSV: header scan,<var>,...; a row sets those variables just before the
                    input read of that scan (1-based); an empty cell leaves the value as it is
  --scans N         number of scans (default: the last stimulus scan, at least 10)
  --cycle TIME      scan cycle, e.g. 10ms, 0.5s, T#100ms (default: the task's interval, else 10ms;
                    tasks at different intervals: their common tick, which --cycle cannot change)
  --watch LIST      comma-separated variables or FB pins (T1.Q), paths into FB instances
                    (Motor1.Run, Line.Motor1.T1.ET) and, for several programs, Instance.Var;
                    default: every variable of the POU in declaration order, FB instances as
                    INSTANCE.PIN (a user FB's VAR_INPUTs and VAR_OUTPUTs)
  --profile NAME    semantics profile: iec (default: the project's) or openplc
  --plant NAME      run the program in closed loop with a machine (rungsmith plants lists them):
                    it advances after every scan by the scan's time; --watch and --inputs take its
                    quantities and operator controls as NAME.x (tank.level, tank.Start) and its
                    faults as "fault ID" columns (1 on, 0 off); consequences (the tank
                    overflowed at scan N) are printed on stderr
Errors (unknown variable, bad value, invalid program) go to stderr with a non-zero exit.`,
  export: `Usage: rungsmith export FILE.json -o OUT.xml

Writes the project as one PLCopen TC6 XML v2.01 document (to stdout without -o).
Prints on stderr, one line per POU network, what Beremiz and OpenPLC would run differently
(warning LD-X01..LD-X08: dropped jumps and RETURNs, function blocks called at the end of the
scan, contacts read again per coil, a connector's OR pasted without brackets, coils in series
after an OR join; LD-X08: networks imported side by side, whose interleaved order the export
cannot draw) and the fix where one exists. The exit code stays 0.`,
  import: `Usage: rungsmith import FILE.xml -o OUT.json

Reads PLCopen TC6 XML (v2.01, v2.0 from CODESYS/TwinCAT, legacy v1.0) into a Rungsmith project
(to stdout without -o). What was dropped or changed is listed on stderr.`,
  test: `Usage: rungsmith test FILE [--junit OUT.xml] [--scenario NAME]

Runs every test scenario stored in the project FILE (its "scenarios": CSV of inputs per scan and
expected values, see docs/scenarios.md) from a cold restart on the virtual clock. Prints
PASS or FAIL per scenario; a failure names the first divergent scan, the expected and actual
values, and "Why?" on the differing output. Then a summary: N passed, N failed.

Options:
  --junit FILE      also write the results as JUnit XML (for CI systems)
  --scenario NAME   run only this scenario
Exits with 1 if any scenario fails (or the project has none), 0 when all pass.`,
  plants: `Usage: rungsmith plants [NAME]

Lists the machines a program can control (docs/PLANTS.md): for each, its I/O map (default
address, name, type, kind: sensor, actuator or operator control), its faults and the quantities
scenarios and --watch read as NAME.quantity. With NAME, that machine alone, with its task.`,
} as const;
