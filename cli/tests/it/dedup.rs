//! The bulk commands `key` and `dedup` on generated inputs with planted
//! copies: the classes are exactly the planted ones, whatever the input
//! format, the thread count or the sharding of `key`.

use crate::common::{bin, cli};
use exact_bezier::strategy::{curve, rect};
use exact_bezier::{
    coincide::Options, coincide::Symmetry, io::coincidence_to_json, io::patch_to_json, ratio, Patch,
};
use num_rational::BigRational;
use proptest::strategy::{Strategy, ValueTree};

use std::collections::BTreeMap;
use std::path::PathBuf;

type Q = BigRational;

/// `bases` random patches (rect and curve), then copies of them moved by
/// Möbius maps, scaling, elevation and symmetries: the patches and the
/// planted class (base id) of each.
fn planted(bases: usize, copies: usize) -> (Vec<Patch<Q>>, Vec<usize>) {
    let mut runner = proptest::test_runner::TestRunner::deterministic();
    let mut all: Vec<Patch<Q>> = (0..bases)
        .map(|k| {
            if k % 4 == 3 {
                Patch::Curve(curve(3, 2).new_tree(&mut runner).unwrap().current())
            } else {
                Patch::Rect(rect(2, 3, 3).new_tree(&mut runner).unwrap().current())
            }
        })
        .collect();
    let mut class: Vec<usize> = (0..bases).collect();
    for c in 0..copies {
        let k = (c * 7 + 3) % bases;
        let alpha = ratio(1 + (c % 9) as i64, 11);
        let beta = ratio(2 + (c % 5) as i64, 9);
        let moved = match &all[k] {
            Patch::Rect(r) => {
                let sym = Symmetry::all().nth(c % 8).unwrap();
                let m = r
                    .mobius_u(&alpha)
                    .mobius_v(&beta)
                    .scale_weights(&ratio(5, 3));
                Patch::Rect(sym.apply_rect(&m.elevate(c % 2, 0)))
            }
            Patch::Curve(cv) => {
                let m = cv.mobius(&alpha).elevate(c % 3);
                Patch::Curve(if c % 2 == 0 { m.reverse() } else { m })
            }
            Patch::Tri(_) => unreachable!(),
        };
        all.push(moved);
        class.push(k);
    }
    (all, class)
}

/// The planted classes: indices grouped by base, classes by first member.
fn expected(class: &[usize]) -> Vec<Vec<u64>> {
    let mut groups: BTreeMap<usize, Vec<u64>> = BTreeMap::new();
    for (k, &c) in class.iter().enumerate() {
        groups.entry(c).or_default().push(k as u64);
    }
    let mut out: Vec<Vec<u64>> = groups.into_values().collect();
    out.sort();
    out
}

fn temp(name: &str) -> PathBuf {
    std::env::temp_dir().join(format!("eb-dedup-{}-{name}", std::process::id()))
}

fn lines_of(patches: &[Patch<Q>]) -> Vec<String> {
    patches
        .iter()
        .map(|p| patch_to_json(p).unwrap().to_string())
        .collect()
}

/// Run the binary with `RAYON_NUM_THREADS = threads`: (code, stdout, stderr).
fn run_with_threads(args: &[&str], threads: &str) -> (i32, String, String) {
    let out = bin()
        .args(args)
        .env("RAYON_NUM_THREADS", threads)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}

/// The `members` of each JSON line of `dedup`'s output.
fn classes_of(stdout: &str) -> Vec<Vec<u64>> {
    stdout
        .lines()
        .enumerate()
        .map(|(id, line)| {
            let v: serde_json::Value = serde_json::from_str(line).unwrap();
            assert_eq!(v["class"], id as u64);
            let members: Vec<u64> = v["members"]
                .as_array()
                .unwrap()
                .iter()
                .map(|m| m.as_u64().unwrap())
                .collect();
            assert_eq!(v["representative"], members[0]);
            members
        })
        .collect()
}

#[test]
fn dedup_finds_exactly_the_planted_classes_in_any_format_and_thread_count() {
    let (patches, class) = planted(12, 30);
    let lines = lines_of(&patches);
    let (jsonl, array) = (temp("in.jsonl"), temp("in.json"));
    std::fs::write(&jsonl, lines.join("\n") + "\n").unwrap();
    std::fs::write(&array, format!("[\n{}\n]", lines.join(",\n"))).unwrap();
    let (jsonl_s, array_s) = (jsonl.to_str().unwrap(), array.to_str().unwrap());

    let one = run_with_threads(&["dedup", jsonl_s], "1");
    assert_eq!(one.0, 0, "{}", one.2);
    assert_eq!(classes_of(&one.1), expected(&class));
    assert_eq!(
        one.2, "",
        "no progress unless asked (stderr is not a terminal)"
    );
    assert_eq!(run_with_threads(&["dedup", jsonl_s], "2").1, one.1);
    assert_eq!(run_with_threads(&["dedup", array_s], "2").1, one.1);
    // --progress writes to stderr only.
    let shown = run_with_threads(&["dedup", jsonl_s, "--progress"], "2");
    assert_eq!(shown.1, one.1);
    assert!(shown.2.contains("42 patches, 12 classes"), "{}", shown.2);

    let k1 = run_with_threads(&["key", jsonl_s], "1");
    assert_eq!(k1.0, 0, "{}", k1.2);
    assert_eq!(run_with_threads(&["key", jsonl_s], "2").1, k1.1);
    assert_eq!(
        run_with_threads(&["key", array_s, "--threads", "2"], "1").1,
        k1.1
    );
    std::fs::remove_file(&jsonl).unwrap();
    std::fs::remove_file(&array).unwrap();
}

/// (index, key) of each line of `key`'s output.
fn keys_of(stdout: &str) -> Vec<(u64, String)> {
    stdout
        .lines()
        .map(|line| {
            let v: serde_json::Value = serde_json::from_str(line).unwrap();
            (
                v["index"].as_u64().unwrap(),
                v["key"].as_str().unwrap().to_string(),
            )
        })
        .collect()
}

#[test]
fn keys_of_shards_in_separate_processes_group_into_the_dedup_classes() {
    let (patches, _) = planted(10, 20);
    let lines = lines_of(&patches);
    let whole = temp("whole.jsonl");
    std::fs::write(&whole, lines.join("\n") + "\n").unwrap();
    let dedup = cli(&["dedup", whole.to_str().unwrap()]);
    assert_eq!(dedup.0, 0, "{}", dedup.2);
    // Three uneven shards, keyed by three processes.
    let mut union = Vec::new();
    let mut start = 0;
    for (s, len) in [7usize, 13, 10].into_iter().enumerate() {
        let shard = temp(&format!("shard{s}.jsonl"));
        std::fs::write(&shard, lines[start..start + len].join("\n")).unwrap();
        let first = start.to_string();
        let out = cli(&["key", shard.to_str().unwrap(), "--first-index", &first]);
        assert_eq!(out.0, 0, "{}", out.2);
        union.extend(keys_of(&out.1));
        std::fs::remove_file(&shard).unwrap();
        start += len;
    }
    assert_eq!(start, lines.len());
    let mut groups: BTreeMap<String, Vec<u64>> = BTreeMap::new();
    for (index, key) in union {
        assert!(key.starts_with("eb1:") && key.len() == 4 + 64, "{key}");
        groups.entry(key).or_default().push(index);
    }
    let mut grouped: Vec<Vec<u64>> = groups.into_values().collect();
    grouped.iter_mut().for_each(|g| g.sort());
    grouped.sort();
    assert_eq!(grouped, classes_of(&dedup.1));
    std::fs::remove_file(&whole).unwrap();
}

/// JSON Lines of the plain shape take the fast reader, the same records as
/// one JSON array the general one: byte-identical keys and key texts, and
/// under `--max-work` the same refusal at the same record (both charge
/// each record the same work).
#[test]
fn the_fast_and_the_general_reader_give_the_same_keys_and_refusals() {
    let (patches, _) = planted(24, 40);
    let lines = lines_of(&patches);
    let jsonl = temp("fast.jsonl");
    std::fs::write(&jsonl, lines.join("\n") + "\n").unwrap();
    let array = temp("general.json");
    std::fs::write(&array, format!("[{}]", lines.join(",\n"))).unwrap();
    let (fast, general) = (jsonl.to_str().unwrap(), array.to_str().unwrap());
    let both = |args: &[&str]| {
        let run = |file: &str| {
            let mut all = vec![args[0], file];
            all.extend(&args[1..]);
            run_with_threads(&all, "2")
        };
        (run(fast), run(general))
    };
    let (a, b) = both(&["key", "--text"]);
    assert_eq!(a.0, 0, "{}", a.2);
    assert_eq!(a, b);
    let (a, b) = both(&["dedup"]);
    assert_eq!(a.0, 0, "{}", a.2);
    assert_eq!(a, b);
    let mut outcomes = Vec::new();
    for budget in ["100000", "1000000", "10000000", "100000000"] {
        let (a, b) = both(&["key", "--max-work", budget]);
        assert_eq!(a, b, "--max-work {budget}");
        outcomes.push(a.0);
    }
    assert!(
        outcomes.contains(&0) && outcomes.contains(&2),
        "{outcomes:?}"
    );
    std::fs::remove_file(&jsonl).unwrap();
    std::fs::remove_file(&array).unwrap();
}

#[test]
fn key_text_is_hashed_into_the_key() {
    use sha2::{Digest, Sha256};
    let (out_code, out, err) = cli(&["key", "tests/fixtures/yang_yong_example1.json", "--text"]);
    assert_eq!(out_code, 0, "{err}");
    let v: serde_json::Value = serde_json::from_str(out.trim()).unwrap();
    let text = v["text"].as_str().unwrap();
    assert!(text.starts_with("eb1;rect;"), "{text}");
    let hex: String = Sha256::digest(text.as_bytes())
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect();
    assert_eq!(v["key"], format!("eb1:{hex}"));
    assert_eq!(v["index"], 0);
}

#[test]
fn witnesses_map_each_representative_to_its_members() {
    let (ex1, ex3) = (
        "tests/fixtures/yang_yong_example1.json",
        "tests/fixtures/yang_yong_example3.json",
    );
    let file = temp("witness.json");
    let text = format!(
        "[{}, {}, {}]",
        crate::common::read_to_string(ex1).unwrap(),
        crate::common::read_to_string(ex3).unwrap(),
        crate::common::read_to_string(ex1).unwrap()
    );
    std::fs::write(&file, text).unwrap();
    let (code, out, err) = cli(&["dedup", file.to_str().unwrap(), "--witness"]);
    std::fs::remove_file(&file).unwrap();
    assert_eq!(code, 0, "{err}");
    let lines: Vec<serde_json::Value> = out
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect();
    assert_eq!(lines.len(), 2);
    assert_eq!(lines[0]["members"], serde_json::json!([0, 2]));
    assert_eq!(lines[0]["witnesses"][0], serde_json::Value::Null);
    assert_eq!(lines[0]["witnesses"][1]["symmetry"], "identity");
    // The identity map: α = β = 1/2, corner weights equal.
    assert_eq!(lines[0]["witnesses"][1]["u"]["alpha"], "1/2");
    assert_eq!(lines[0]["witnesses"][1]["corner_weight_ratio"], 1);
    assert_eq!(lines[1]["members"], serde_json::json!([1]));
    assert_eq!(lines[1]["witnesses"], serde_json::json!([null]));
}

#[test]
fn witnesses_of_moved_copies_are_those_of_coincide() {
    let (patches, class) = planted(4, 6);
    let file = temp("moved.jsonl");
    std::fs::write(&file, lines_of(&patches).join("\n")).unwrap();
    let (code, out, err) = cli(&["dedup", file.to_str().unwrap(), "--witness"]);
    std::fs::remove_file(&file).unwrap();
    assert_eq!(code, 0, "{err}");
    for line in out.lines() {
        let v: serde_json::Value = serde_json::from_str(line).unwrap();
        let members = v["members"].as_array().unwrap();
        let rep = members[0].as_u64().unwrap() as usize;
        for (m, w) in members
            .iter()
            .zip(v["witnesses"].as_array().unwrap())
            .skip(1)
        {
            let m = m.as_u64().unwrap() as usize;
            assert_eq!(class[m], class[rep]);
            let c =
                exact_bezier::coincide::coincide(&patches[rep], &patches[m], Options::default())
                    .unwrap();
            assert_eq!(*w, coincidence_to_json(&c)["witness"]);
        }
    }
}

#[test]
fn bad_records_are_located_and_stop_with_code_2() {
    let good = r#"{"kind": "curve", "points": [[0, 0], [1, 2], [3, 0]], "weights": [1, 2, 1]}"#;
    let cases = [
        (
            format!("{good}\n\n{{\"kind\": \"curve\", \"points\": [[0]]\n"),
            "line 3",
        ),
        (
            format!("{good}\n{}\n", good.replace("[1, 2, 1]", "[1, -2, 1]")),
            "line 2",
        ),
        (
            format!("[{good}, {{\"kind\": \"tri\", \"points\": [[[0]], [[1], [2]]]}}]"),
            "element 1",
        ),
        (format!("[{good}, {good}"), "EOF"),
    ];
    for (k, (text, want)) in cases.iter().enumerate() {
        let file = temp(&format!("bad{k}.json"));
        std::fs::write(&file, text).unwrap();
        for cmd in ["dedup", "key"] {
            let (code, out, err) = cli(&[cmd, file.to_str().unwrap()]);
            assert_eq!(code, 2, "{cmd} case {k}: {out}");
            assert!(
                err.starts_with("error: ") && err.contains(want),
                "{cmd} case {k}: {err}"
            );
        }
        std::fs::remove_file(&file).unwrap();
    }
    assert_eq!(cli(&["dedup", "no/such/file.jsonl"]).0, 2);
    // Empty input: no classes, no keys.
    let empty = temp("empty.jsonl");
    std::fs::write(&empty, "\n").unwrap();
    assert_eq!(
        cli(&["dedup", empty.to_str().unwrap()]),
        (0, String::new(), String::new())
    );
    std::fs::remove_file(&empty).unwrap();
}

/// `--max-digits` reaches the readers on every worker thread: a record of
/// 300 digits among others is refused under 20 and accepted under 5000,
/// and one of 2000 digits (over the default) is accepted under 5000.
#[test]
fn max_digits_holds_on_every_thread() {
    let plain = r#"{"kind": "curve", "points": [[0], [1], [3]], "weights": [1, 2, 1]}"#;
    let long = |digits: usize| {
        format!(
            r#"{{"kind": "curve", "points": [[0], [1], [{}]], "weights": [1, 2, 1]}}"#,
            "9".repeat(digits)
        )
    };
    for digits in [300, 2000] {
        let path = temp(&format!("digits-{digits}.jsonl"));
        std::fs::write(&path, format!("{plain}\n{}\n{plain}\n", long(digits))).unwrap();
        let p = path.to_str().unwrap();
        for command in ["key", "dedup"] {
            for threads in ["1", "2"] {
                let (code, _, err) = run_with_threads(&["--max-digits", "20", command, p], threads);
                assert_eq!(code, 2, "{command} {digits} digits: {err}");
                assert!(
                    err.contains(&format!(
                        "line 2: over a limit: a number of {digits} digits"
                    )),
                    "{err}"
                );
                // `dedup --witness` also re-reads the representatives on the workers.
                let (args, lines) = match command {
                    "key" => (vec!["--max-digits", "5000", "key", p], 3),
                    _ => (vec!["--max-digits", "5000", "dedup", p, "--witness"], 2),
                };
                let (code, out, err) = run_with_threads(&args, threads);
                assert_eq!((code, out.lines().count()), (0, lines), "{err}");
            }
        }
        std::fs::remove_file(&path).unwrap();
    }
}
