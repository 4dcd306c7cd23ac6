//! The text of `kinsyn sweep` (a run, resumed or complete) and `kinsyn sweep merge`.

use kinsyn_report::sweep::{CHECKPOINT, JSONL, MANIFEST, Manifest, PARQUET, SweepOutcome};
use std::fmt::Write as _;
use std::path::Path;

/// The text report of a run of `kinsyn sweep`, with `--bench`'s figures.
pub(in crate::cli) fn run(o: &SweepOutcome, bench: bool) -> String {
    let m = &o.manifest;
    let shard = m.shard.map_or_else(String::new, |s| format!(", shard {s}"));
    let what = format!(
        "{} designs of {} ({}; {} legs, {} actuated per leg, seed {}{shard})",
        m.designs,
        m.sweep_designs,
        m.selection,
        m.settings.legs,
        m.settings
            .actuated_per_leg
            .iter()
            .map(ToString::to_string)
            .collect::<Vec<_>>()
            .join(" or "),
        m.settings.sampling.seed,
    );
    if o.already_complete {
        return format!(
            "{}: already complete with {what}; nothing rewritten\n",
            o.out
        );
    }
    let mut s = format!(
        "{}: {what}: {} evaluated, resumed {} rows, {} errors; ",
        o.out, o.evaluated, o.resumed, o.errors
    );
    if o.complete {
        let _ = writeln!(s, "complete: {JSONL}, {PARQUET}, {MANIFEST}");
    } else {
        let _ = writeln!(
            s,
            "stopped with {} of {} rows in {CHECKPOINT}; run the same command again to resume",
            o.resumed + o.evaluated,
            m.designs
        );
    }
    if bench {
        let _ = writeln!(s, "designs evaluated      {}", o.evaluated);
        let _ = writeln!(s, "lock subsets sampled   {}", o.lock_subsets);
        let _ = writeln!(s, "wall seconds           {:.3}", o.seconds);
        let _ = writeln!(s, "designs/s              {:.2}", o.designs_per_second());
        let _ = writeln!(
            s,
            "subsets per core-s     {:.1}",
            o.subsets_per_core_second()
        );
        let _ = writeln!(s, "threads                {}", o.threads);
        let _ = writeln!(s, "writing ms             {:.1}", o.write_ms);
    }
    s
}

/// The text report of `kinsyn sweep merge`: `shards` directories merged into `out`, whose
/// manifest is `manifest`.
pub(in crate::cli) fn merged(out: &Path, shards: usize, manifest: &Manifest) -> String {
    format!(
        "{}: merged {shards} shards: {} designs ({}); {JSONL}, {PARQUET}, {MANIFEST}\n",
        out.display(),
        manifest.designs,
        manifest.selection
    )
}
