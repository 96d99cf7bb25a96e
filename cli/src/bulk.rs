//! What `key` and `dedup` share: the input as a counted byte stream, keys
//! of a chunk of records on all cores, the progress bar, the exit code.

use crate::recent::{RecentKeys, RecordHash};
use exact_bezier::algebra::RealAlgebraic;
use exact_bezier::algebra::Scalar;
use exact_bezier::coincide::canonical::{key_plan, DigestHasher, KeyDigest, KeyPlan};
use exact_bezier::io::{for_each_chunk, Record};
use exact_bezier::limits::{self, Size};
use exact_bezier::patch::Patch;
use exact_bezier::Error;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle, TermLike};
use num_rational::BigRational;
use rayon::prelude::*;
use std::collections::HashMap;
use std::hash::BuildHasherDefault;
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
    pub fn open(&self) -> Result<(Box<dyn BufRead + Send>, Input), Error> {
        if let Some(n) = self.threads {
            // Fails only if the pool was already built (tests in one process).
            let _ = rayon::ThreadPoolBuilder::new()
                .num_threads(n.max(1))
                .build_global();
        }
        let bytes = Arc::new(AtomicU64::new(0));
        let (inner, size): (Box<dyn Read + Send>, Option<u64>) = if self.file == "-" {
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

/// The key of a line of the plain shape that the fast reader keyed in
/// machine integers as it read it
/// ([`SmallPatch::certify`](exact_bezier::coincide::canonical::SmallPatch::certify)):
/// the digest of its key text, and the text when the command prints it.
#[derive(Clone)]
pub(crate) struct MachineKey {
    pub digest: KeyDigest,
    pub text: Option<String>,
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
    pub(crate) fn algebraic(&self) -> Result<Patch<RealAlgebraic>, Error> {
        Ok(match self {
            Member::Rational(p) => p.map(RealAlgebraic::from_rational),
            Member::Algebraic(p) => p.clone(),
        })
    }

    /// The key work of `r` and its key (text kept if `texts`) or its
    /// patch, by the fast reader, when it is a line of the plain shape
    /// whose net is certified minimal: the key when its text stays in
    /// machine integers ([`KeyPlan::Machine`]), else the patch over Q
    /// ([`KeyPlan::Minimal`]). The work is that [`key_work`] charges the
    /// same patch read by [`Member::read`]:
    /// [`SmallPatch::certify`](exact_bezier::coincide::canonical::SmallPatch::certify)
    /// has run the machine-integer key text, which decides the
    /// [`KeyPlan`] as [`key_plan`] does.
    ///
    /// A net with a homogeneous number outside `i128` (no
    /// [`SmallPatch::size`](exact_bezier::coincide::canonical::SmallPatch::size))
    /// goes to the general reader; the bits of the size are counted only
    /// when they are charged ([`KeyPlan::Minimal`]).
    fn read_fast(r: &Record, texts: bool) -> Option<(Result<MachineKey, Member>, u64)> {
        let mut s = r.small_patch()?;
        if !s.homogeneous_fits() || !s.certify() {
            return None;
        }
        if !s.machine_keyed() {
            let work = rational_key_work(KeyPlan::Minimal, &s.size()?);
            return Some((Err(Member::Rational(s.to_patch().ok()?)), work));
        }
        let work = machine_key_work(s.degree(), s.dim());
        let text = s.into_key_text().ok()?;
        let key = MachineKey {
            digest: KeyDigest::of_text(&text),
            text: texts.then_some(text),
        };
        Some((Ok(key), work))
    }
}

/// The estimated work of one record's canonical key (docs/limits.md),
/// before its exact part is computed: over Q, [`rational_key_work`] of the
/// record's [`KeyPlan`]. Over the real algebraic numbers: the model of
/// `coincide` and the signs that order the normalized points (charged as
/// one point written, [`limits::write_ops`]: a sign refines an isolating
/// interval), times the cost of one operation in the field the record's
/// numbers span, refused when that field is over the field degree limit.
///
/// # Errors
///
/// As [`key_plan`] (a tri patch, a weight ≤ 0).
pub(crate) fn key_work(p: &Member) -> Result<u64, Error> {
    Ok(match p {
        Member::Algebraic(p) => {
            let s = p.size();
            if s.field {
                limits::check_field_degree(s.field_degree, false, "an algebraic record")?;
            }
            let (ops, bits) = super::coincide::coincide_cost(&s);
            s.exact_units(ops + s.write_ops(s.dim as u64 + 1), bits)
        }
        Member::Rational(q) => rational_key_work(key_plan(q)?, &q.size()),
    })
}

/// The estimated key work of a record over Q of size `size` computed by
/// `plan`, read modulo p: a net whose key stays in machine integers costs
/// [`machine_key_work`]; a certified net whose key leaves them adds the
/// `BigRational` key ([`big_key_work`]); an elevated copy adds to the
/// change of basis modulo p one exact pass that undoes the elevation
/// (`O(size · degree)`) and is then charged as a patch of the lower degree
/// by the model of `coincide`; anything else is charged the model of
/// `coincide`.
fn rational_key_work(plan: KeyPlan, size: &Size) -> u64 {
    let coincide = |s: &Size| {
        let (ops, bits) = super::coincide::coincide_cost(s);
        s.exact_units(ops, bits)
    };
    match plan {
        KeyPlan::Machine => machine_key_work(size.degree, size.dim),
        KeyPlan::Minimal => {
            machine_key_work(size.degree, size.dim).saturating_add(big_key_work(size))
        }
        KeyPlan::General => coincide(size),
        KeyPlan::Elevated(to) => {
            let lower = Size {
                degree: to,
                ..*size
            };
            let undo = (size.degree.0 as u64 + 1)
                * (size.degree.1 as u64 + 1)
                * (lower.total_degree() + 2)
                * (size.dim as u64 + 1);
            modp_work(size.degree, size.dim)
                .saturating_add(limits::exact_work(undo, size.bits))
                .saturating_add(coincide(&lower))
        }
    }
}

/// The size of a record and the degree its canonical form is computed at:
/// the degree of the elevated copy's lower net for a record over Q that
/// [`key_plan`] finds elevated, its own degree otherwise.
pub(crate) fn least_degree(p: &Member) -> Result<(Size, (usize, usize)), Error> {
    let rational = |q: &Patch<BigRational>| -> Result<(Size, (usize, usize)), Error> {
        let s = q.size();
        Ok(match key_plan(q)? {
            KeyPlan::Elevated(to) => (s, to),
            KeyPlan::Machine | KeyPlan::Minimal | KeyPlan::General => (s, s.degree),
        })
    };
    match p {
        Member::Rational(q) => rational(q),
        Member::Algebraic(q) => {
            let s = q.size();
            Ok((s, s.degree))
        }
    }
}

/// The change of basis modulo p that certifies a net of (bi)degree
/// `(m, n)` in dimension `d`: `(m+1)(n+1)(m+n+2)(d+1)` word operations.
fn modp_work((m, n): (usize, usize), dim: usize) -> u64 {
    let (m1, n1) = (m as u64 + 1, n as u64 + 1);
    m1 * n1 * (m1 + n1) * (dim as u64 + 1)
}

/// Work units of one machine-integer operation of the key (reading a
/// number, a product, a comparison or a digit of text on fractions of
/// `i128`), per number of the net and symmetry: calibrated by
/// `cli/benches/cost_model.rs`.
const MACHINE_OPS_PER_NUMBER: u64 = 48;

/// The work of the key of a certified minimal net of (bi)degree `(m, n)`
/// in dimension `d` whose numbers stay in machine integers: the change of
/// basis modulo p ([`modp_work`]) and [`MACHINE_OPS_PER_NUMBER`] per stored
/// number (`(m+1)(n+1)(d+1)` of them), whatever their bits (at most 127
/// each).
fn machine_key_work((m, n): (usize, usize), dim: usize) -> u64 {
    let numbers = (m as u64 + 1) * (n as u64 + 1) * (dim as u64 + 1);
    modp_work((m, n), dim).saturating_add(MACHINE_OPS_PER_NUMBER.saturating_mul(numbers))
}

/// The work of the key of a certified minimal net of size `s` over
/// `BigRational`: the points, invariants and digest of up to 8 symmetries
/// (`16(m+1)(n+1)(d+1)` exact operations on numbers of `bits·(N+1)` bits:
/// two per point and symmetry, calibrated by `cli/benches/cost_model.rs`).
fn big_key_work(s: &Size) -> u64 {
    let (m1, n1) = (s.degree.0 as u64 + 1, s.degree.1 as u64 + 1);
    limits::exact_work(
        16 * m1 * n1 * (s.dim as u64 + 1),
        s.bits.max(8).saturating_mul(s.total_degree() + 1),
    )
}

/// A fresh record of [`key_chunk`] as read: its key (when the fast reader
/// keyed it) or its patch, and its key work.
type Fresh<K> = (Result<K, Member>, u64);

/// `key` on every record of a chunk, results in input order: a record
/// whose text the chunk has already had, or `recent` still holds, is not
/// keyed again ([`RecentKeys`]); every other record is first charged its
/// [`key_work`] against the work budget as `what`, in input order on this
/// thread (so `--max-work` refuses at the same record whatever the thread
/// count; the refusal names the 0-based index of that record, `first`
/// being the chunk's first). The records are read and keyed on all cores,
/// and their keys kept in `recent`; a line the fast reader keys as it reads
/// it gets its [`MachineKey`] (with its text if `texts`) as its key. The
/// error reported is that of the first failing record in input order,
/// located.
pub(crate) fn key_chunk<K: Clone + Send + Sync + From<MachineKey>>(
    what: &str,
    texts: bool,
    first: usize,
    records: &[Record],
    recent: &mut RecentKeys<K>,
    key: impl Fn(Member) -> Result<K, Error> + Sync,
) -> Result<Vec<K>, Error> {
    let hashes: Vec<RecordHash> = records
        .par_iter()
        .map(|r| KeyDigest::of_text(&r.text()).0)
        .collect();
    // Each record's key: one `recent` holds, or that of a fresh record.
    let mut fresh = Vec::new();
    // Keyed by SHA-256 digests: their first bytes are hash enough.
    let mut in_chunk: HashMap<RecordHash, usize, BuildHasherDefault<DigestHasher>> =
        HashMap::default();
    let source: Vec<Result<K, usize>> = hashes
        .iter()
        .enumerate()
        .map(|(k, h)| match recent.get(h) {
            Some(key) => Ok(key.clone()),
            None => Err(*in_chunk.entry(*h).or_insert_with(|| {
                fresh.push(k);
                fresh.len() - 1
            })),
        })
        .collect();
    let command_limits = limits::current();
    let read: Vec<Result<Fresh<K>, Error>> = fresh
        .par_iter()
        .map(|&k| {
            let r = &records[k];
            // A worker's own limits are the defaults: the command's
            // (`--max-digits`) are this thread's.
            limits::with_limits(command_limits, || {
                if let Some((read, work)) = Member::read_fast(r, texts) {
                    return Ok((read.map(K::from), work));
                }
                let p = Member::read(r)?;
                let work = key_work(&p).map_err(|e| r.locate(e))?;
                Ok((Err(p), work))
            })
        })
        .collect();
    let mut members = Vec::with_capacity(read.len());
    for (&k, done) in fresh.iter().zip(read) {
        let (p, work) = done?;
        // Nothing is charged on a refusal: the second charge refuses too,
        // naming the record (a name not formatted for every record).
        limits::charge(what, work)
            .or_else(|_| limits::charge(&format!("{what} (through record {})", first + k), work))?;
        members.push(p);
    }
    let keyed: Vec<Result<K, Error>> = members
        .into_par_iter()
        .zip(&fresh)
        .map(|(p, &k)| p.or_else(|p| key(p).map_err(|e| records[k].locate(e))))
        .collect();
    let keyed = keyed.into_iter().collect::<Result<Vec<K>, Error>>()?;
    for (&k, key) in fresh.iter().zip(&keyed) {
        recent.put(hashes[k], key.clone());
    }
    Ok(source
        .into_iter()
        .map(|s| s.unwrap_or_else(|i| keyed[i].clone()))
        .collect())
}

/// Chunks read ahead of the one being keyed ([`for_each_chunk_ahead`]).
const READ_AHEAD: usize = 2;

/// [`for_each_chunk`] of `reader` in chunks of [`CHUNK`] with the reading
/// on a thread of its own, up to [`READ_AHEAD`] chunks ahead of `f` (which
/// runs on this thread): reading overlaps keying. The same chunks in the
/// same order, and the same first error: an error of `f` stops the
/// reading; a read error is returned once `f` has had every chunk before
/// it. The reader runs under this thread's limits.
pub(crate) fn for_each_chunk_ahead(
    reader: Box<dyn BufRead + Send>,
    mut f: impl FnMut(usize, Vec<Record>) -> Result<(), Error>,
) -> Result<usize, Error> {
    let limits = limits::current();
    let (tx, rx) = std::sync::mpsc::sync_channel(READ_AHEAD);
    std::thread::scope(|scope| {
        let reading = scope.spawn(move || {
            limits::with_limits(limits, || {
                for_each_chunk(reader, CHUNK, |first, records| {
                    // Fails only when `f` failed and the receiver is gone.
                    tx.send((first, records))
                        .map_err(|_| Error::Io("the keying stopped".into()))
                })
            })
        });
        let consumed = rx.iter().try_for_each(|(first, records)| f(first, records));
        // Unblock a reader waiting for room before joining it.
        drop(rx);
        let read = reading
            .join()
            .unwrap_or_else(|panic| std::panic::resume_unwind(panic));
        consumed.and(read)
    })
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
        self.end_line();
    }

    /// Write one line formatted from `args`, straight into the block.
    pub fn line_args(&mut self, args: std::fmt::Arguments<'_>) {
        use std::fmt::Write as _;
        // Writing into a String cannot fail.
        let _ = self.buffer.write_fmt(args);
        self.end_line();
    }

    fn end_line(&mut self) {
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

#[cfg(test)]
mod tests {
    use super::*;
    use exact_bezier::coincide::canonical::canonical_text;
    use exact_bezier::limits::Limits;
    use proptest::prelude::*;

    /// The key text of a member over Q (the pool has no other).
    fn text_of(p: Member) -> Result<String, Error> {
        match p {
            Member::Rational(q) => canonical_text(&q),
            Member::Algebraic(_) => Err(Error::Domain("not a rational record".into())),
        }
    }

    /// The text of a key the fast reader computed (kept: `keyed` asks for
    /// the texts).
    impl From<MachineKey> for String {
        fn from(k: MachineKey) -> String {
            k.text.unwrap_or_default()
        }
    }

    /// Quadratic curves of small integers: some certified minimal, some
    /// not (equal points, collinear ones).
    fn pool() -> impl Strategy<Value = Vec<String>> {
        let curve = (prop::array::uniform3(-2i32..3), 1i32..4).prop_map(|(x, w)| {
            format!(
                r#"{{"kind": "curve", "points": [[{}], [{}], [{}]], "weights": [1, {w}, 1]}}"#,
                x[0], x[1], x[2]
            )
        });
        prop::collection::vec(curve, 1..6)
    }

    /// `key_chunk` over `records` in chunks of `chunk`, with a table of
    /// `2^log2` slots: the keys and the work charged.
    fn keyed(records: &[Record], chunk: usize, log2: u32) -> (Vec<String>, u64) {
        limits::with_limits(Limits::DEFAULT, || {
            let mut recent = RecentKeys::new(log2);
            let mut keys = Vec::new();
            for (c, part) in records.chunks(chunk).enumerate() {
                keys.extend(key_chunk("key", true, c * chunk, part, &mut recent, text_of).unwrap());
            }
            (keys, limits::charged())
        })
    }

    proptest! {
        #[test]
        fn a_small_table_gives_every_record_its_own_key(
            pool in pool(),
            picks in prop::collection::vec(any::<prop::sample::Index>(), 1..40),
            chunk in 1usize..9,
            log2 in 0u32..3,
        ) {
            let records: Vec<Record> = picks
                .iter()
                .enumerate()
                .map(|(k, i)| Record::Line(k + 1, i.get(&pool).clone()))
                .collect();
            let plain: Vec<String> = records
                .iter()
                .map(|r| text_of(Member::read(r).unwrap()).unwrap())
                .collect();
            let work = |r: &Record| key_work(&Member::read(r).unwrap()).unwrap();
            let every: u64 = records.iter().map(work).sum();
            let distinct: HashMap<String, u64> =
                records.iter().map(|r| (r.text().into_owned(), work(r))).collect();
            let (keys, charged) = keyed(&records, chunk, log2);
            prop_assert_eq!(keys, plain);
            // Each record is charged at most once, each distinct text at least once.
            prop_assert!(charged <= every);
            prop_assert!(charged >= distinct.values().sum::<u64>());
        }
    }

    /// Quadratic curves whose weights are small or of up to 40 bits (then
    /// the key of some leaves machine integers).
    fn curve_line() -> impl Strategy<Value = String> {
        let weight = prop_oneof![1u64..5, 1u64..1 << 40];
        (
            prop::array::uniform3(-9i32..9),
            prop::array::uniform3(weight),
        )
            .prop_map(|(x, w)| {
                format!(
                    r#"{{"kind": "curve", "points": [[{}], [{}], [{}]], "weights": [{}, {}, {}]}}"#,
                    x[0], x[1], x[2], w[0], w[1], w[2]
                )
            })
    }

    proptest! {
        #[test]
        fn the_fast_reader_charges_what_the_general_one_does(line in curve_line()) {
            let r = Record::Line(1, line);
            let general = key_work(&Member::read(&r).unwrap()).unwrap();
            if let Some((_, fast)) = Member::read_fast(&r, false) {
                prop_assert_eq!(fast, general);
            }
        }
    }

    #[test]
    fn a_repeated_record_is_keyed_and_charged_once() {
        let text = r#"{"kind": "curve", "points": [[0], [1], [3]], "weights": [1, 2, 1]}"#;
        let records: Vec<Record> = (1..=50).map(|n| Record::Line(n, text.into())).collect();
        let one = key_work(&Member::read(&records[0]).unwrap()).unwrap();
        // Across chunks (through the table) and within one chunk.
        for chunk in [1, 7, 50] {
            assert_eq!(keyed(&records, chunk, 0).1, one);
        }
    }
}
