//! Command-line interface: parses arguments, runs the library, prints results.
//!
//! Exit codes (docs/limits.md): 0 success (also `--help`, `--version`, and a reader that went
//! away); 2 bad input (arguments, chain strings, patterns, poses, input values, files that are
//! missing or not descriptions, faulty fields, limits); 1 an environment failure (an output that
//! cannot be written) or a damaged build (a compiled-in catalogue that does not read). Errors are one line on stderr, prefixed `kinsyn: error:`, with echoed
//! input escaped ([`terminal::one_line`]).

mod args;
mod catalogue;
mod export;
mod hexa_plot;
mod notation;
mod plot;
mod render;
mod site;
mod sweep_command;
mod view;
pub use sweep_command::parquet_bytes;
mod sweep_report;
mod terminal;

/// The commands as functions (`kinsyn-report`), under the names the command's modules use.
use kinsyn_report::{
    Error as CliError, components, configurable, json, list_or_none, manipulator, output, solve,
    solve_shards, sorted_json, sweep,
};

use args::{Cli, Command};
use clap::Parser;

pub use kinsyn_report::Error;

/// Runs the command line on the process's arguments, printing the result on stdout and errors
/// on stderr, and returns the process exit code (0, 1 or 2, as above).
#[must_use]
pub fn run() -> i32 {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) if e.use_stderr() => {
            terminal::error(&format!("{} (see kinsyn --help)", usage_error(&e)));
            return 2;
        }
        Err(e) => {
            // --help and --version: their text is the result.
            let mut text = e.render().to_string();
            if !text.ends_with('\n') {
                text.push('\n');
            }
            return match terminal::print(&text) {
                Ok(()) => 0,
                Err(_) => 1,
            };
        }
    };
    #[cfg(unix)]
    file_size_limit_is_an_error();
    let result = execute(cli.command).and_then(|text| {
        terminal::print(&text).map_err(|e| {
            CliError::Io(std::io::Error::new(
                e.kind(),
                format!("cannot write standard output: {e}"),
            ))
        })
    });
    match result {
        Ok(()) => 0,
        Err(e) => {
            terminal::error(&e.to_string());
            match e {
                CliError::Input(_) => 2,
                CliError::Io(_) | CliError::Internal(_) => 1,
            }
        }
    }
}

/// Makes a file-size limit (`ulimit -f`) reached while writing an error of that write (EFBIG,
/// "File too large"), reported with the file's path after the temporary file is removed
/// ([`kinsyn::output`]), instead of the signal SIGXFSZ, whose default is to kill kinsyn on the
/// spot and leave the temporary file behind.
#[cfg(unix)]
fn file_size_limit_is_an_error() {
    let ignored = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
    // Registering fails only for the signals that cannot be caught, which SIGXFSZ is not; if
    // it ever did, the signal would only keep its default.
    let _ = signal_hook::flag::register(signal_hook::consts::SIGXFSZ, ignored);
}

/// A command-line mistake in one line: what is missing or wrong, with the names of the
/// arguments or subcommands concerned (clap spreads these over several lines).
fn usage_error(e: &clap::Error) -> String {
    use clap::error::{ContextKind, ContextValue, ErrorKind};
    let values = |kind| match e.get(kind) {
        Some(ContextValue::Strings(v)) => v.join(", "),
        Some(ContextValue::String(v)) => v.clone(),
        _ => String::new(),
    };
    match e.kind() {
        ErrorKind::MissingSubcommand | ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            let command = values(ContextKind::InvalidSubcommand);
            let available = values(ContextKind::ValidSubcommand);
            format!(
                "{} needs a subcommand: {}",
                if command.is_empty() {
                    "kinsyn".into()
                } else {
                    command
                },
                available
            )
        }
        ErrorKind::MissingRequiredArgument => {
            format!(
                "missing required argument {}",
                values(ContextKind::InvalidArg)
            )
        }
        _ => {
            // The message lines, without the usage and "for more information" footer.
            let text = e.render().to_string();
            text.lines()
                .map(str::trim)
                .take_while(|l| !l.starts_with("Usage:") && !l.starts_with("For more information"))
                .filter(|l| !l.is_empty())
                .map(|l| l.trim_start_matches("error: "))
                .collect::<Vec<_>>()
                .join(" ")
        }
    }
}

#[allow(
    clippy::too_many_lines,
    reason = "a dispatcher: one arm per subcommand, each only naming its options"
)]
fn execute(command: Command) -> Result<String, CliError> {
    if matches!(command, Command::Plot(_)) {
        plot::register_font();
    }
    match command {
        Command::Notation { chain, json } => notation::notation(&chain, json),
        Command::Catalogue(c) => catalogue::catalogue(c),
        Command::Query {
            pattern,
            max_locks,
            family,
            json: as_json,
            reading,
        } => catalogue::query(&pattern, max_locks, family.as_deref(), as_json, &reading),
        Command::Modes {
            file,
            pose,
            max_locks,
            lock,
            max_subsets,
            body,
            relative_to,
            legs,
            sampling,
            json: as_json,
        } => {
            let selection = match (lock, max_locks) {
                (Some(set), _) => manipulator::Selection::Lock(set),
                (None, Some(k)) => manipulator::Selection::MaxLocks(k),
                (None, None) => manipulator::Selection::All,
            };
            let loaded = manipulator::modes(
                &file,
                (pose.as_deref(), body.as_deref(), relative_to.as_deref()),
                legs.as_deref(),
                &selection,
                max_subsets,
                &sampling.settings(),
            )?;
            render::warn(&file, &loaded.warnings);
            let (m, modes) = (&loaded.manipulator, &loaded.result);
            Ok(if as_json {
                sorted_json(&manipulator::modes_report(
                    m,
                    modes,
                    pose.as_deref(),
                    &selection,
                    &loaded.warnings,
                ))
            } else {
                render::modes::text(m, modes, pose.as_deref(), &selection)
            })
        }
        Command::Analyze {
            file,
            inputs,
            body,
            all_assemblies: true,
            seed,
            json: as_json,
            ..
        } => {
            let loaded =
                manipulator::all_assemblies(&file, inputs.as_deref(), body.as_deref(), seed)?;
            render::warn(&file, &loaded.warnings);
            let (m, all) = (&loaded.manipulator, &loaded.result);
            Ok(if as_json {
                sorted_json(&all.report(m, &loaded.warnings))
            } else {
                render::assemblies::text(m, all, &file)
            })
        }
        Command::Analyze {
            file,
            pose,
            inputs,
            from,
            lock,
            body,
            relative_to,
            study,
            nearest,
            rounding,
            seed,
            json: as_json,
            ..
        } => {
            let loaded = manipulator::analyze(
                &file,
                &manipulator::Placement {
                    pose: pose.as_deref(),
                    inputs: inputs.as_deref(),
                    from: from.as_deref(),
                    body: body.as_deref(),
                    study: &study,
                    nearest: nearest.then_some(rounding),
                    relative_to: relative_to.as_deref(),
                },
                lock.as_deref(),
                &kinsyn::mechanism::SampleSettings {
                    seed,
                    ..Default::default()
                },
            )?;
            render::warn(&file, &loaded.warnings);
            let m = &loaded.manipulator;
            let report = loaded.result.report(m, &loaded.warnings);
            Ok(if as_json {
                sorted_json(&report)
            } else {
                render::analyze::text(m, &report)
            })
        }
        Command::Build {
            spec,
            output,
            force,
        } => manipulator::build_command(&spec.into(), output.as_deref(), force.force),
        Command::Solve {
            file,
            start,
            seed,
            runs,
            threads,
            max_paths,
            show,
            no_certify,
            json: as_json,
            shard,
            out,
            force,
            merge,
        } => {
            let options = solve::SolveOptions {
                start: start.into(),
                seed,
                runs,
                threads,
                max_paths,
                certify: !no_certify,
                show: show.into(),
            };
            if let (Some(shard), Some(out)) = (shard, out) {
                let shard = solve_shards::parse_shard(&shard)?;
                let summary = solve_shards::solve_shard_file(&file, &options, shard, &out, force)?;
                return Ok(if as_json {
                    json(&summary)
                } else {
                    render::solve::shard_text(&summary)
                });
            }
            let solved = if merge.is_empty() {
                solve::solve(&file, &options)?
            } else {
                solve_shards::merge_shard_files(&file, &options, &merge)?
            };
            render::warn(&file, &solved.warnings());
            Ok(if as_json {
                json(&solved.json())
            } else {
                render::solve::text(&solved)
            })
        }
        Command::Components {
            file,
            inputs,
            free_inputs,
            free,
            body,
            method,
            seed,
            max_paths,
            json: as_json,
        } => {
            let c = components::components_of(
                &file,
                &components::ComponentsOptions {
                    seed,
                    method: method.into(),
                    inputs,
                    free_inputs,
                    free,
                    body,
                    max_paths,
                },
            )?;
            Ok(if as_json {
                sorted_json(&c.report())
            } else {
                render::components::text(&c)
            })
        }
        Command::Configurable(c) => match c {
            args::ConfigurableCommand::Inverse {
                centre,
                c4,
                theta,
                phi,
                json: as_json,
            } => {
                let r = configurable::inverse_report(centre.as_deref(), c4.as_deref(), theta, phi)?;
                Ok(if as_json {
                    sorted_json(&r)
                } else {
                    render::configurable::inverse(&r)
                })
            }
            args::ConfigurableCommand::Forward {
                q,
                method,
                json: as_json,
            } => {
                let r = configurable::forward_report(&q, method)?;
                Ok(if as_json {
                    sorted_json(&r)
                } else {
                    render::configurable::forward(&r)
                })
            }
            args::ConfigurableCommand::Velocity {
                q,
                qdot,
                near,
                json: as_json,
            } => {
                let r = configurable::velocity_report(&q, &qdot, near.as_deref())?;
                Ok(if as_json {
                    sorted_json(&r)
                } else {
                    render::configurable::velocity(&r)
                })
            }
        },
        Command::Plot(args::PlotCommand::Inverse {
            out,
            force,
            centre,
            theta,
            phi,
        }) => {
            let c = configurable::numbers("--centre", &centre, 2)?;
            plot::inverse(&out, force.force, (c[0], c[1]), theta, phi)
        }
        Command::Plot(args::PlotCommand::Trajectory {
            out,
            force,
            steps,
            json: as_json,
        }) => plot::trajectory(&out, force.force, steps, as_json),
        Command::Plot(args::PlotCommand::Workspace {
            hexa,
            step,
            json: as_json,
        }) => hexa_plot::workspace(&hexa, step, as_json),
        Command::Plot(args::PlotCommand::Indices {
            hexa,
            z,
            step,
            workspace_step,
            json: as_json,
        }) => hexa_plot::indices(
            &hexa,
            &hexa_plot::IndexOptions {
                phi: (hexa.phi1, hexa.phi2),
                z,
                step,
                workspace_step,
            },
            as_json,
        ),
        Command::Stack {
            modules,
            radii,
            heights,
            output,
            force,
        } => manipulator::stack_command(&modules, radii, heights, output.as_deref(), force.force),
        Command::Export {
            file,
            mjcf,
            urdf,
            force,
        } => export::models(&file, mjcf.as_deref(), urdf.as_deref(), force.force),
        Command::View {
            file,
            out,
            inputs,
            steps,
            no_assemblies,
            components,
            free_inputs,
            max_paths,
            seed,
            json,
            force,
        } => view::view(
            &file,
            &out,
            &kinsyn_report::view::ViewOptions {
                inputs,
                steps,
                assemblies: !no_assemblies,
                components,
                free_inputs,
                max_paths,
                seed,
            },
            force.force,
            json,
        ),
        Command::Sweep {
            command: Some(args::SweepCommand::Report(r)),
            ..
        } => sweep_report::report(&r),
        Command::Sweep {
            command:
                Some(args::SweepCommand::Merge {
                    dirs,
                    out,
                    force,
                    json,
                }),
            ..
        } => sweep_command::merge_command(&dirs, &out, force.force, json),
        Command::Sweep { run, command: None } => {
            let out = run
                .out
                .ok_or_else(|| CliError::Input("kinsyn sweep needs --out DIR".into()))?;
            sweep_command::command(
                &out,
                &sweep::Request {
                    legs: run.legs,
                    actuated: &run.actuated,
                    seed: run.seed,
                    chains: run.chains.as_deref(),
                    family: run.family.as_deref(),
                    shard: run.shard.as_deref(),
                    threads: run.threads,
                    stop_after: run.stop_after,
                    force: run.force,
                },
                run.bench,
                run.json,
            )
        }
    }
}
