// fogbench-cli: the headless bench. Wires the simulator, the decoder and the
// analysis together; see `fogbench-cli help`.

#include <iostream>
#include <set>
#include <string>
#include <vector>

#include "app/cli_arguments.h"
#include "app/catalog_command.h"
#include "app/cli_commands.h"
#include "core/common/memory.h"
#include "core/common/version.h"
#include "app/batch_command.h"
#include "app/diagnose_command.h"
#include "app/noise_command.h"
#include "app/response_command.h"
#include "app/session_commands.h"
#include "app/cli_common.h"
#include "core/session/stored_result.h"
#ifdef FOG_HAVE_REPORT
#include "app/report_command.h"
#endif
#include "app/serial_command.h"

namespace {

const char* kHelp = R"(fogbench-cli: measure how late a fiber-optic gyro IMU reports rotation.

usage:
  fogbench-cli run [plan] [simulator options] [constants] [--limit-ms 0.8] [--coverage-k 2]
                  [--save-raw FILE [--overwrite]] [--json]
      Run a test plan on the built-in simulator and print the delay report.
      plan: --plan FILE.json
            | --preset paper|paper-slow|paper-fast|quick|noise|response|response-third-octave (default
            paper: 0.1 Hz / 10 deg for 294 s and 1 Hz / 3 deg for 60 s on X; response: 20 frequencies
            0.05 .. 11 Hz on X; response-third-octave: the standard plan, the 21 nominal one-third
            octaves 0.1 .. 10 Hz (0.1, 0.125, 0.16 .. 8, 10) on X, the table's whole reach; either
            response on the axis --axis names)
            | --axis x --freq-hz 0.1 --amp-deg 10 --duration-s 294 [--settle-s 5]
      --source sim (default), --seed N, --speed X (X times real time; default 0:
      as fast as possible),
      --gyro-delay-ms D (gyro's own delay, default 0.2358),
      --arw-deg-sqrt-h, --bias-instability-deg-h, --pulse-equivalent-deg,
      --table-freq-error-ppm, --counter-hz, --counter-bits, --counter-start,
      --latitude-deg, --heading-deg (table x axis from north toward east),
      --imu-clock-ppm, --imu-period-ms, --table-period-ms, --encoder-quantum-deg,
      --bias-x-deg-h, --bias-y-deg-h, --bias-z-deg-h,
      nominal-chain constants (docs/simulator.md; 0 = off):
      --register-period-ms P [--register-offset-ms O] (pulse register updated every P,
      first at O, held until the next: the paper's 0.5), --boxcar-ms T (rate averaged
      over T), --rate-filter-ms T (first-order rate filter), --rate-filter-hz F
      [--rate-filter-damping Z] (second-order rate filter, default damping 0.7),
      --base-tilt-deg B [--base-tilt-azimuth-deg A] (table base tilted by B about the
      horizontal axis at azimuth A), --nonorthogonality-arcsec N (between adjacent
      table axes), --eccentricity-um E [--eccentricity-radius-mm R, default 100]
      [--eccentricity-phase-deg P] (encoder error E/R sin(angle + P)),
      --lost-table-per-mille L (table frames lost),
      --effect NAME=V[,V][+NAME=V...] (unmodelled effects from docs/diagnosis.md,
      e.g. scale_factor_error=200)
      --out SESSION.fbs [--operator NAME --imu-model M --imu-serial S --lot L --bench-id B --notes TEXT]:
            record the run into a new session file (raw stream, samples, result); --lot: the
            IMU's production lot, --bench-id: the bench (station) recording it. The result's
            audit entry names the operator (else the login name), the command line and the
            SHA-256 of the raw stream. --db CATALOG: the catalog the stored result goes to
            (else the folder's fogbench-catalog.sqlite when it has one; docs/catalog.md); a
            catalog that cannot be reached never fails the run (stderr says how to catch up).
  fogbench-cli run --source serial --port DEV [--baud 921600] [--parity none|even|odd]
                  [--data-bits 8] [--stop-bits 1] [--stall-warning-s 2] [--stall-timeout-s 10]
                  [plan] [constants] [--out SESSION.fbs ...] [--json]
      Record a sampling board on a serial port until its plan is done;
      the plan, if given, is stored as the one intended (the board runs its own).
      A port that vanishes or a line silent for --stall-timeout-s ends the run as
      incomplete, keeping everything received (docs/serial.md). The board is sent
      start/stop streaming and the pulse equivalent if given (docs/protocol.md,
      "Host to board"); --no-board-commands sends nothing.
  fogbench-cli run --table remote:tcp:HOST:PORT|remote:DEV|manual --source serial --port DEV
                  [plan] [constants] [--table-heartbeat-s 2] [--table-reply-timeout-s 2]
                  [--table-baud 115200] [--operator-timeout-s 600] [--speed X] [--out SESSION.fbs ...]
      Drive the turntable through the plan while recording the board:
      remote: a controller speaking the protocol of docs/table-control.md; manual:
      the operator is told what to set and the table angle decides when it is right.
      Test points are cut from the table angle; Ctrl+C or any fault brings the table
      to rest; the session keeps the table log. --table sim (default): the simulator.
  fogbench-cli ports
      List the serial ports.
  fogbench-cli response FILE [constants] [--json] [--at-hz 5]
      The gyro's frequency response (gyro angle / table angle) at every swing
      point of an axis that passed its checks: magnitude and phase with their
      sigma, then the pure-delay, first-order and second-order models fitted to
      them (sigma, correlation, chi2, AIC, BIC; chosen by AIC), the -3 dB
      bandwidth and the group delay at --at-hz; per point the phase against the
      table's motion with its expanded uncertainty U (k = 2) in deg and ms, the
      table read delay's uncertainty (--read-delay-std-ms, else the session's) in
      the budget. run --preset response records one; --preset response-third-octave
      the standard plan.
  fogbench-cli analyze FILE [constants] [--limit-ms 0.8] [--coverage-k 2] [--json] [--no-store] [--operator NAME]
                       [--db CATALOG]
      The same report from a saved raw sampling-board byte stream, or from a
      session file (its own bench constants unless given; the result is stored
      in the session as a new row unless --no-store). The verdict is pass, fail
      (IMU delay + k sigma >= limit) or invalid (a validity check failed:
      reversed axis, clock rate, not a steady sinusoid, negative delay).
      --coverage-k K: the decision rule's coverage factor (default 2, within
      (0, 10]), stored with the result; every report states the rule and its
      false-accept risk 1 - Phi(k) (2.28 % at k = 2; docs/report.md).
      The stored result's audit entry: who (--operator, else the login name), this
      command line, the constants, the version and the SHA-256 of the raw stream.
      The session is then re-indexed into the catalog (--db, else its folder's
      fogbench-catalog.sqlite when there is one); one that cannot be reached never
      fails the analysis: stderr says so and how to catch up (catalog index DIR).
  fogbench-cli batch DIR|FILE... --jsonl OUT.jsonl [--jobs N] [constants] [--limit-ms 0.8] [--coverage-k 2]
                     [--operator NAME] [--db CATALOG]
      Re-analyse many sessions (the *.fbs files under each DIR, recursively; FILEs as
      given; each file once however named: in, ./in, a link) with the constants given (each session's own where not given) and store
      each result as a new one, as analyze does (with its audit entry: --operator or
      the login name, this command line). OUT.jsonl gets a header line (the
      settings) and one line per file as it finishes: "stored", "already_stored" or
      "refused" with the error; the verdict and, only where vouched for, each test
      point's IMU delay (else why it is refused). --jobs: files at a time (default the
      number of cores, at most 8). Run it again with the same OUT to resume: files
      listed are skipped, a line cut short by a kill is discarded, a result stored
      before its line was written is not stored twice; an OUT of other settings is
      refused. Progress on a terminal; a summary at the end. Then the catalog (--db, else
      the first DIR's fogbench-catalog.sqlite when there is one) re-indexes the sessions
      changed. Exit 1 when a file was refused (every file still has its line); 3 when
      the catalog could not be updated (the results are stored).
  fogbench-cli sessions DIR [--json]
      List the sessions in a folder: date, operator, IMU, lot, bench, axes, state, latest lag.
  fogbench-cli replay SESSION.fbs [--speed X | --afap] [constants] [--limit-ms 0.8] [--coverage-k 2] [--json]
      Feed a session's raw stream through the decoder at X times real time
      (default 1) or as fast as possible, and report.
  fogbench-cli import DIR | META.json TABLE.csv GYRO.csv --out SESSION.fbs [--segment auto|S-E,...]
                     [--rate-convention frame_average|sample_at_stamp] [--frame-period-ms P]
                     [--operator NAME --imu-model M --imu-serial S --lot L --bench-id B --notes TEXT]
      Make a session of data from another bench (the CSV layout of docs/formats.md);
      --segment cuts a continuous recording into its steady-swing windows;
      --rate-convention says how a gyro file of rates was sampled when its metadata
      does not (with the IMU's frame period for frame_average). Both are stored with
      the session and every result of it.
  fogbench-cli export SESSION.fbs [--csv DIR] [--hdf5 FILE.h5] [--results-json FILE.json] [--overwrite] [constants]
                     [--limit-ms L] [--coverage-k K]
      Decoded samples, fits and residuals as CSV (readable back by import);
      the same values, the per-period track and the shown result in one HDF5
      file (docs/formats.md, "HDF5 export"); the stored results and the current analysis as JSON.
  fogbench-cli theory [--freq-hz F --amp-deg A --duration-s T] [--stability-deg-h S]
                      [--fibre-length-m L] [--arw-deg-sqrt-h N] [--json]
      The paper's delay budget and resolution figure, and the bench's bound.
  fogbench-cli accuracy [--seeds N] [--threads K]
      Monte Carlo study of both paper conditions (docs/accuracy.md).
  fogbench-cli report (SESSION.fbs | FILE.bin | --preset NAME [--seed N]) [--pdf OUT.pdf] [--png-dir DIR [--dpi 100]]
                      [--overwrite] [--limit-ms 0.8] [--coverage-k 2] [--imu-model M --imu-serial S --operator NAME]
                      [--lot L --bench-id B]
                      [--language en|zh_CN] [constants]
      The calibration report (docs/report.md): PASS when every validity check passes
      and IMU delay + k sigma < limit (k = 2 unless --coverage-k); the report states
      this decision rule, its k and its false-accept risk. A session brings its own
      identity and constants. A session with a stored result is reported as stored
      (its settings, limit, k and verdict; INCOMPLETE for a run stopped early):
      --limit-ms, --coverage-k and constants apply only to data without one
      (analyze stores another analysis first). Prints the unit (IMU, serial, lot,
      bench, operator) and the session's audit trail, one line per stored result;
      the PDF has it under "Analyses of this session".
  fogbench-cli diagnose SESSION.fbs|FILE.bin [--json] [--seeds K] [--threads T]
                        [--bias-instability DEG_H [--bias-correlation S]] [constants]
      Sim-to-real gap diagnosis (docs/diagnosis.md): where real and simulated data
      differ, which effect explains it, held-out shrink, alias groups, verdict.
      The IMU's bias instability (its static noise test) sharpens the gyro-trend
      test; unstated, 0.5 deg/h over 300 s is assumed.
  fogbench-cli bench-diagnosis [--trials N] [--seed S] [--threads T]
      Self-consistency check of the diagnosis: fogbench's own simulator with the
      library's effects withheld, diagnosed with the same library (not blind to
      its parameterisation; tests/independent/blind_reference.py is).
  fogbench-cli noise SESSION.fbs|FILE.bin [--json] [--axis x|y|z] [--taus-per-octave N]
                     [--freq-hz F --amp-deg A --duration-s T] [--latitude-deg L] [--imu-frame F]
                     [--kalibr-yaml IMU.yaml [--overwrite]]
      Gyro noise from the static segments (docs/noise.md): Allan deviation with
      confidence intervals, IEEE 952 noise terms (also in SI units), bias,
      Earth-corrected bias and the predicted lag sigma of a swing test;
      --kalibr-yaml writes the IMU noise file kalibr and OpenVINS read. Exit 1
      when there is no static segment.
  fogbench-cli catalog index DIR|FILE... [--db FILE|FOLDER|postgresql://...] [--json | --csv]
      The lab's record (docs/catalog.md): one row per stored result of every
      session under the folders (unit, lot, bench, verdict, IMU delay per point
      only when vouched for, constants, software, who analysed it, the file's
      SHA-256). Unchanged files are not reopened; a damaged file is one refusal.
      Default catalog: the first folder's fogbench-catalog.sqlite. --db: a SQLite
      file, a folder (its fogbench-catalog.sqlite) or a PostgreSQL server, named
      only as a postgresql:// or postgres:// URI (anything else is a file); with a
      server, the first folder's own catalog is indexed and its pending rows pushed
      (exit 3 when the server does not answer: they stay pending for the next index,
      batch or push).
  fogbench-cli catalog units [--lot L] | unit SERIAL | lot LOT [--limit-ms L] | refused
                       [--db ...] [--json | --csv]
      Units and their latest verdicts; one unit's history (verdict, delay +- sigma,
      temperature, constants, software, who; its delay against temperature); a
      lot's pass rate, first-pass yield, delay mean and spread, and Cpk.
  fogbench-cli catalog push --from LOCAL.sqlite|FOLDER --db postgresql://... [--json | --csv]
      Sends the results not yet sent to a shared catalog (a bench that indexed
      offline pushes when the server is back; a repeated push adds nothing).
  fogbench-cli --version | help

constants: --read-delay-ms (0.05) --read-delay-std-ms (0) --board-delay-ms (0.28)
           --board-delay-std-ms (0) --pulse-equivalent-deg (when the stream lacks it)
           --gyro-sign x=-1[,y=-1,z=-1] (a gyro axis mounted the other way round)
           --imu-frame NED|ENU|FRD[:H]|RFU[:H] (the IMU's axes at zero table angles; H: azimuth
             of its forward axis; unstated, the diagnosis finds z's direction from the data)
           --gain-tolerance F (0.01: the gyro/table ratio, its fitted dynamics out, within 1 +- F)
           delays and their uncertainties within 0 .. 1000 ms, a pulse equivalent within 1e-9 .. 1 deg
exit codes: 0 ok, 1 the data gave no result, 2 bad command line or input.
)";

}  // namespace

int main(int argc, char** argv) {
  fog::keepFreedMemoryForReuse();
  fog::app::setAuditCommandLine(fog::session::commandLineOf("fogbench-cli", argc, argv));
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "help" || args[0] == "--help" || args[0] == "-h") {
    std::cout << kHelp;
    return args.empty() ? 2 : 0;
  }
  if (args[0] == "--version" || args[0] == "version") {
    std::cout << "fogbench-cli " << FOG_VERSION << "\n";
    return 0;
  }
  const std::string command = args[0];
  args.erase(args.begin());
  for (const std::string& a : args) {
    if (a == "--help" || a == "-h") {
      std::cout << kHelp;
      return 0;
    }
  }
  // `catalog` reads --csv as a flag (CSV on stdout); `export --csv DIR` takes a folder.
  std::set<std::string> flags = {"json", "no-store", "afap", "overwrite", "no-board-commands"};
  if (command == "catalog") flags.insert("csv");
  auto parsed = fog::app::CliArguments::parse(args, flags);
  if (!parsed) {
    std::cerr << "fogbench-cli: " << parsed.status().message() << "\n";
    return 2;
  }
  if (command == "run") return fog::app::runCommand(*parsed);
  if (command == "catalog") return fog::app::catalogCommand(*parsed);
  if (command == "ports") {
    return fog::app::portsCommand(*parsed);
  }
  if (command == "analyze") return fog::app::analyzeCommand(*parsed);
  if (command == "batch") return fog::app::batchCommand(*parsed);
  if (command == "sessions") return fog::app::sessionsCommand(*parsed);
  if (command == "replay") return fog::app::replayCommand(*parsed);
  if (command == "import") return fog::app::importCommand(*parsed);
  if (command == "export") return fog::app::exportCommand(*parsed);
  if (command == "theory") return fog::app::theoryCommand(*parsed);
  if (command == "accuracy") return fog::app::accuracyCommand(*parsed);
  if (command == "diagnose") return fog::app::diagnoseCommand(*parsed);
  if (command == "bench-diagnosis") return fog::app::benchDiagnosisCommand(*parsed);
  if (command == "noise") return fog::app::noiseCommand(*parsed);
  if (command == "response") return fog::app::responseCommand(*parsed);
  if (command == "report") {
#ifdef FOG_HAVE_REPORT
    return fog::app::reportCommand(*parsed);
#else
    std::cerr << "fogbench-cli: this build has no report renderer (no Qt/Qwt); build with the release preset\n";
    return 2;
#endif
  }
  std::cerr << "fogbench-cli: unknown command '" << command << "' (try fogbench-cli help)\n";
  return 2;
}
