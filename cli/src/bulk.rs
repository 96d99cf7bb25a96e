//! What `key` and `dedup` share: the input as a counted byte stream, keys
//! of a chunk of records on all cores, the progress bar, the exit code.

use exact_bezier::algebra::RealAlgebraic;
use exact_bezier::algebra::Scalar;
use exact_bezier::io::Record;
use exact_bezier::patch::Patch;
use exact_bezier::Error;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle, TermLike};
use num_rational::BigRational;
use rayon::prelude::*;
use std::io::{BufRead, BufReader, IsTerminal, Read, Write};
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;
use std::time::Instant;

/// Records handed to the workers at a time.
pub(crate) const CHUNK: usize = 4096;

/// Options common to the bulk commands.
#[derive(clap::Args, Debug)]
pub(crate) struct BulkArgs {
    /// Input: JSON Lines (one curve or rect patch per line) or a JSON array; - for standard input.
    pub file: String,
    /// Show a progress bar on standard error even when it is not a terminal
    /// (then one status line per second).
    #[arg(long)]
    pub progress: bool,
    /// Worker threads (default: all cores, or RAYON_NUM_THREADS).
    #[arg(long)]
    pub threads: Option<usize>,
}

/// Counts the bytes read through it (for the progress bar).
struct Counted<R> {
    inner: R,
    bytes: Arc<AtomicU64>,
}

impl<R: Read> Read for Counted<R> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        let n = self.inner.read(buf)?;
        self.bytes.fetch_add(n as u64, Ordering::Relaxed);
        Ok(n)
    }
}

/// What the progress bar knows of an opened input: its size if known and
/// the bytes read so far.
pub(crate) struct Input {
    pub size: Option<u64>,
    pub bytes: Arc<AtomicU64>,
}

impl BulkArgs {
    /// Set the thread count and open the input.
    pub fn open(&self) -> Result<(Box<dyn BufRead>, Input), Error> {
        if let Some(n) = self.threads {
            // Fails only if the pool was already built (tests in one process).
            let _ = rayon::ThreadPoolBuilder::new()
                .num_threads(n.max(1))
                .build_global();
        }
        let bytes = Arc::new(AtomicU64::new(0));
        let (inner, size): (Box<dyn Read>, Option<u64>) = if self.file == "-" {
            (super::stdin_reader(), None)
        } else {
            let f = std::fs::File::open(&self.file)
                .map_err(|e| Error::Io(format!("cannot read {}: {e}", self.file)))?;
            let size = f.metadata().ok().map(|m| m.len());
            (Box::new(f), size)
        };
        let counted = Counted {
            inner,
            bytes: Arc::clone(&bytes),
        };
        let reader = Box::new(BufReader::with_capacity(1 << 16, counted));
        Ok((reader, Input { size, bytes }))
    }
}

/// The patch of one record: over Q when its numbers are all rational (and
/// for NURBS objects), else over the real algebraic numbers.
pub(crate) enum Member {
    /// Every number rational.
    Rational(Patch<BigRational>),
    /// Some number algebraic and irrational (`"sqrt(6)/6"`).
    Algebraic(Patch<RealAlgebraic>),
}

impl Member {
    /// Read `r`; a record neither reader accepts gets the rational
    /// reader's error.
    pub(crate) fn read(r: &Record) -> Result<Member, Error> {
        match r.patch() {
            Ok(p) => Ok(Member::Rational(p)),
            Err(e) => r.patch_as().map(Member::Algebraic).map_err(|_| e),
        }
    }

    /// The patch over the real algebraic numbers (a rational one lifted).
    pub(crate) fn algebraic(&self) -> Patch<RealAlgebraic> {
        match self {
            Member::Rational(p) => p.map(RealAlgebraic::from_rational),
            Member::Algebraic(p) => p.clone(),
        }
    }
}

/// Refuse a record over the real algebraic numbers whose canonical key
/// would cost more than the work budget `max` (the model of `coincide`,
/// times the operation cost of its numbers: general roots make every
/// operation a resultant). Records over Q are not charged: their cost is
/// bounded by their size.
///
/// # Errors
///
/// [`Error::Limit`] naming the estimate and `--max-work`.
pub(crate) fn check_record_cost(p: &Patch<RealAlgebraic>, max: u64) -> Result<(), Error> {
    let size = p.size();
    let (ops, bits) = super::coincide::coincide_cost(&size);
    let units = size.exact_units(ops, bits);
    if units > max {
        return Err(Error::Limit(format!(
            "this record's algebraic numbers need an estimated {units:.2e} work units, over the budget of {max:.2e} (raise it with --max-work)"
        )));
    }
    Ok(())
}

/// `f` on the patch of every record of a chunk, in parallel, results in
/// input order. The error reported is that of the first failing record in
/// input order, whatever the thread count; errors of `f` are located too.
pub(crate) fn map_chunk<T: Send>(
    records: &[Record],
    f: impl Fn(Member) -> Result<T, Error> + Sync,
) -> Result<Vec<T>, Error> {
    let done: Vec<Result<T, Error>> = records
        .par_iter()
        .map(|r| f(Member::read(r)?).map_err(|e| r.locate(e)))
        .collect();
    done.into_iter().collect()
}

/// A progress bar on standard error: bytes read against the input size
/// (with ETA), patches done and their rate. Hidden unless standard error is
/// a terminal or `--progress` asks for it.
pub(crate) struct Progress {
    bar: Option<ProgressBar>,
    start: Instant,
}

/// A non-terminal target: each redraw becomes one line.
#[derive(Debug)]
struct LogLines;

impl TermLike for LogLines {
    fn width(&self) -> u16 {
        100
    }
    fn move_cursor_up(&self, _: usize) -> std::io::Result<()> {
        Ok(())
    }
    fn move_cursor_down(&self, _: usize) -> std::io::Result<()> {
        Ok(())
    }
    fn move_cursor_right(&self, _: usize) -> std::io::Result<()> {
        Ok(())
    }
    fn move_cursor_left(&self, _: usize) -> std::io::Result<()> {
        Ok(())
    }
    fn write_line(&self, s: &str) -> std::io::Result<()> {
        writeln!(std::io::stderr(), "{s}")
    }
    fn write_str(&self, s: &str) -> std::io::Result<()> {
        // No cursor to return to: every redraw is a line of its own.
        if s.trim().is_empty() {
            return Ok(());
        }
        writeln!(std::io::stderr(), "{}", s.trim_end())
    }
    fn clear_line(&self) -> std::io::Result<()> {
        Ok(())
    }
    fn flush(&self) -> std::io::Result<()> {
        std::io::stderr().flush()
    }
}

impl Progress {
    pub fn new(args: &BulkArgs, input: &Input) -> Progress {
        let terminal = std::io::stderr().is_terminal();
        let bar = (terminal || args.progress).then(|| {
            let target = if terminal {
                ProgressDrawTarget::stderr()
            } else {
                ProgressDrawTarget::term_like_with_hz(Box::new(LogLines), 1)
            };
            let (bar, template) = match input.size {
                Some(n) => (
                    ProgressBar::with_draw_target(Some(n), target),
                    "{elapsed_precise} [{bar:30}] {percent:>3}% {msg}, ETA {eta}",
                ),
                None => (
                    ProgressBar::with_draw_target(None, target),
                    "{elapsed_precise} {spinner} {msg}",
                ),
            };
            if let Ok(style) = ProgressStyle::with_template(template) {
                bar.set_style(style.progress_chars("=> "));
            }
            bar.set_message("0 patches");
            bar
        });
        Progress {
            bar,
            start: Instant::now(),
        }
    }

    /// Report `done` patches and the bytes read so far.
    pub fn update(&self, input: &Input, done: usize) {
        if let Some(bar) = &self.bar {
            let secs = self.start.elapsed().as_secs_f64().max(1e-3);
            bar.set_message(format!("{done} patches ({:.0}/s)", done as f64 / secs));
            bar.set_position(input.bytes.load(Ordering::Relaxed));
        }
    }

    /// Close the bar with a summary line.
    pub fn finish(&self, summary: &str) {
        if let Some(bar) = &self.bar {
            let secs = self.start.elapsed().as_secs_f64();
            bar.finish_and_clear();
            eprintln!("{summary} in {secs:.1} s");
        }
    }
}

/// The run's standard output ([`emit_raw`](super::emit_raw)), written in
/// blocks of about 64 KiB so that a million lines are not a million writes.
pub(crate) struct Out {
    buffer: String,
}

/// The block size of [`Out`].
const OUT_BLOCK: usize = 1 << 16;

impl Out {
    pub fn new() -> Out {
        Out {
            buffer: String::with_capacity(OUT_BLOCK + 256),
        }
    }

    /// Write one line.
    pub fn line(&mut self, text: &str) {
        self.buffer.push_str(text);
        self.buffer.push('\n');
        if self.buffer.len() >= OUT_BLOCK {
            self.flush();
        }
    }

    /// Write what is buffered.
    pub fn flush(&mut self) {
        super::emit_raw(&self.buffer);
        self.buffer.clear();
    }
}
