use super::*;

fn names(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

#[test]
fn nothing_is_written_until_the_commit_and_nothing_stays_without_it() {
    let dir = tempfile::tempdir().unwrap();
    let a = dir.path().join("a.png");
    let mut outs = Outputs::new();
    let o = outs.file("-o", &a, &["png"]).unwrap();
    let s = outs.dir("--slices", &dir.path().join("s")).unwrap();
    outs.write(o, |w| w.write_all(b"x")).unwrap();
    outs.write_in(s, "z0.png", |w| w.write_all(b"y")).unwrap();
    assert!(!a.exists());
    drop(outs);
    assert!(names(dir.path()).is_empty(), "{:?}", names(dir.path()));
    assert!(pending().iter().all(|p| !p.starts_with(dir.path())));
}

#[test]
fn commit_puts_files_and_directories_in_place() {
    let dir = tempfile::tempdir().unwrap();
    let a = dir.path().join("a.png");
    let mut outs = Outputs::new();
    let o = outs.file("-o", &a, &["png"]).unwrap();
    let s = outs.dir("--slices", &dir.path().join("s/t")).unwrap();
    outs.write(o, |w| w.write_all(b"x")).unwrap();
    outs.write_in(s, "z0.png", |w| w.write_all(b"y")).unwrap();
    outs.commit().unwrap();
    assert_eq!(names(dir.path()), ["a.png", "s"]);
    assert_eq!(std::fs::read(&a).unwrap(), b"x");
    assert_eq!(std::fs::read(dir.path().join("s/t/z0.png")).unwrap(), b"y");
}

#[test]
fn a_tree_replaces_a_directory_of_its_format_whole_and_refuses_others() {
    let dir = tempfile::tempdir().unwrap();
    let store = dir.path().join("v.zarr");
    std::fs::create_dir_all(store.join("0/c/9")).unwrap();
    std::fs::write(store.join("zarr.json"), b"old").unwrap();
    std::fs::write(store.join("0/c/9/stale"), b"old").unwrap();
    let mut outs = Outputs::new();
    let t = outs.tree("-o", &store, &["zarr"], "zarr.json").unwrap();
    let root = outs.stage_root(t).unwrap();
    std::fs::create_dir_all(root.join("0")).unwrap();
    std::fs::write(root.join("zarr.json"), b"new").unwrap();
    assert_eq!(std::fs::read(store.join("zarr.json")).unwrap(), b"old");
    outs.commit().unwrap();
    assert_eq!(names(dir.path()), ["v.zarr"]);
    assert_eq!(names(&store), ["0", "zarr.json"]);
    assert_eq!(std::fs::read(store.join("zarr.json")).unwrap(), b"new");
    assert!(
        names(&store.join("0")).is_empty(),
        "the old chunks are gone"
    );

    // A directory of other files is refused when named, and kept.
    let other = dir.path().join("photos.zarr");
    std::fs::create_dir(&other).unwrap();
    std::fs::write(other.join("a.jpg"), b"x").unwrap();
    let mut outs = Outputs::new();
    let e = outs
        .tree("-o", &other, &["zarr"], "zarr.json")
        .unwrap_err()
        .to_string();
    assert!(e.contains("holds no zarr.json"), "{e}");
    let e = outs
        .tree("-o", &dir.path().join("v.nrrd"), &["zarr"], "zarr.json")
        .unwrap_err()
        .to_string();
    assert!(e.contains("must end in .zarr"), "{e}");
    // Staged and dropped: nothing new stays.
    let t = outs
        .tree("-o", &dir.path().join("new.zarr"), &["zarr"], "zarr.json")
        .unwrap();
    std::fs::write(outs.stage_root(t).unwrap().join("zarr.json"), b"x").unwrap();
    drop(outs);
    assert_eq!(names(dir.path()), ["photos.zarr", "v.zarr"]);
    assert_eq!(names(&other), ["a.jpg"]);
}

/// `-o LINK/` and `-o LINK` alike write the store the link names and keep the link (with
/// the slash the link was replaced by a directory).
#[cfg(unix)]
#[test]
fn a_store_through_a_symlink_keeps_it_with_or_without_a_trailing_slash() {
    let dir = tempfile::tempdir().unwrap();
    let store = dir.path().join("v.zarr");
    std::fs::create_dir(&store).unwrap();
    std::fs::write(store.join("zarr.json"), b"old").unwrap();
    let link = dir.path().join("l.zarr");
    std::os::unix::fs::symlink("v.zarr", &link).unwrap();
    for (k, spelling) in [
        format!("{}/", link.display()),
        format!("{}//", link.display()),
    ]
    .into_iter()
    .chain([link.display().to_string()])
    .enumerate()
    {
        let mut outs = Outputs::new();
        let t = outs
            .tree("-o", Path::new(&spelling), &["zarr"], "zarr.json")
            .unwrap();
        let root = outs.stage_root(t).unwrap();
        std::fs::write(root.join("zarr.json"), format!("new {k}")).unwrap();
        outs.commit().unwrap();
        let kept = std::fs::symlink_metadata(&link).unwrap().file_type();
        assert!(kept.is_symlink(), "{spelling}: the link was replaced");
        let got = std::fs::read_to_string(store.join("zarr.json")).unwrap();
        assert_eq!(got, format!("new {k}"), "{spelling}");
    }
    assert_eq!(names(dir.path()), ["l.zarr", "v.zarr"]);
}

#[test]
fn a_series_takes_only_its_names_and_replaces_only_a_series() {
    let dir = tempfile::tempdir().unwrap();
    let s = dir.path().join("s");
    std::fs::create_dir(&s).unwrap();
    for k in 0..3 {
        std::fs::write(s.join(format!("z{k}.png")), b"old").unwrap();
    }
    let mut outs = Outputs::new();
    let o = outs.series("--slices", &s, "z", ".png").unwrap();
    outs.write_in(o, "z7.png", |w| w.write_all(b"new")).unwrap();
    for bad in ["z.png", "zz1.png", "z1.png.bak", "a1.png"] {
        let e = outs.write_in(o, bad, |_| Ok(())).unwrap_err().to_string();
        assert!(e.contains("bad file name"), "{e}");
    }
    outs.commit().unwrap();
    assert_eq!(names(&s), ["z7.png"]);
    assert_eq!(names(dir.path()), ["s"]);
    let mut outs = Outputs::new();
    for path in [".", "..", "s/.."] {
        let e = outs.series("--slices", Path::new(path), "z", ".png");
        let e = e.unwrap_err().to_string();
        assert!(e.contains("names no directory"), "{path}: {e}");
    }
}

#[test]
fn extensions_directories_and_missing_parents_are_refused_when_named() {
    let dir = tempfile::tempdir().unwrap();
    let mut outs = Outputs::new();
    let e = outs
        .file("-o", &dir.path().join("x.jpg"), &["png"])
        .unwrap_err()
        .to_string();
    assert!(e.contains("must end in .png"), "{e}");
    let e = outs.file("-o", dir.path(), &[]).unwrap_err().to_string();
    assert!(e.contains("is a directory"), "{e}");
    let e = outs
        .file("-o", &dir.path().join("no/x.png"), &["png"])
        .unwrap_err()
        .to_string();
    assert!(e.contains("directory"), "{e}");
    let e = outs
        .file("-o", Path::new("-"), &["png"])
        .unwrap_err()
        .to_string();
    assert!(e.contains("standard output"), "{e}");
    outs.file_or_stdout("-o", Path::new("-"), &["png"]).unwrap();
    let e = outs
        .file_or_stdout("--preview", Path::new("-"), &["png"])
        .unwrap_err()
        .to_string();
    assert!(e.contains("only one output"), "{e}");
    let p = dir.path().join("a.png");
    outs.file("-o", &p, &["png"]).unwrap();
    let e = outs.file("--mesh", &p, &["png"]).unwrap_err().to_string();
    assert!(e.contains("same file"), "{e}");
}

#[cfg(unix)]
#[test]
fn symlinks_are_followed_and_kept() {
    let dir = tempfile::tempdir().unwrap();
    let real = dir.path().join("real.png");
    let link = dir.path().join("link.png");
    std::fs::write(&real, b"old").unwrap();
    std::os::unix::fs::symlink("real.png", &link).unwrap();
    write_atomic(&link, |w| w.write_all(b"new")).unwrap();
    assert!(std::fs::symlink_metadata(&link)
        .unwrap()
        .file_type()
        .is_symlink());
    assert_eq!(std::fs::read(&real).unwrap(), b"new");
    // A dangling symlink: the file it names is created.
    let dangling = dir.path().join("d.png");
    std::os::unix::fs::symlink("made.png", &dangling).unwrap();
    write_atomic(&dangling, |w| w.write_all(b"m")).unwrap();
    assert_eq!(std::fs::read(dir.path().join("made.png")).unwrap(), b"m");
}

#[cfg(unix)]
#[test]
fn an_existing_files_mode_is_kept() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("a.csv");
    std::fs::write(&p, b"old").unwrap();
    std::fs::set_permissions(&p, std::fs::Permissions::from_mode(0o600)).unwrap();
    write_atomic(&p, |w| w.write_all(b"new")).unwrap();
    let mode = std::fs::metadata(&p).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode, 0o600);
}

#[test]
fn a_staged_directory_is_removed_while_files_are_still_created_in_it() {
    let dir = tempfile::tempdir().unwrap();
    for _ in 0..20 {
        let staged = dir.path().join(".s.x.csgpix-tmp");
        std::fs::create_dir(&staged).unwrap();
        let stop = std::sync::Arc::new(std::sync::atomic::AtomicBool::new(false));
        let writer = {
            let (staged, stop) = (staged.clone(), stop.clone());
            std::thread::spawn(move || {
                // As a run writes its slices: one file after another, by path, until
                // the directory is gone.
                let mut n = 0;
                while !stop.load(std::sync::atomic::Ordering::Relaxed) {
                    let _ = std::fs::write(staged.join(format!("z{n:05}.png")), b"x");
                    n += 1;
                }
            })
        };
        while std::fs::read_dir(&staged).unwrap().count() < 50 {
            std::thread::yield_now();
        }
        remove_staged(&staged);
        stop.store(true, std::sync::atomic::Ordering::Relaxed);
        writer.join().unwrap();
        assert!(names(dir.path()).is_empty(), "{:?}", names(dir.path()));
    }
}

#[cfg(unix)]
#[test]
fn character_devices_are_written_through() {
    write_atomic(Path::new("/dev/null"), |w| w.write_all(b"discarded")).unwrap();
    let m = std::fs::metadata("/dev/null").unwrap();
    use std::os::unix::fs::FileTypeExt;
    assert!(m.file_type().is_char_device());
}

/// Replacing a file (`replace`): the target holds the new bytes, with the old file's mode; the
/// old file is swapped out whole, not rewritten (a hard link to it still reads the old
/// bytes); no staged name stays; and the same with `sync_outputs`, and for the files of a
/// directory output. A `write` that runs twice stages the second content only.
#[cfg(unix)]
#[test]
fn a_replaced_file_is_swapped_whole_and_nothing_else_stays() {
    use std::os::unix::fs::PermissionsExt;
    for sync in [false, true] {
        sync_outputs(sync);
        let dir = tempfile::tempdir().unwrap();
        let d = dir.path();
        let (a, link) = (d.join("a.nrrd"), d.join("old-link"));
        std::fs::write(&a, b"old bytes").unwrap();
        std::fs::set_permissions(&a, std::fs::Permissions::from_mode(0o640)).unwrap();
        std::fs::hard_link(&a, &link).unwrap();
        std::fs::create_dir(d.join("s")).unwrap();
        std::fs::write(d.join("s/z0.png"), b"old slice").unwrap();
        let mut outs = Outputs::new();
        let o = outs.file("-o", &a, &["nrrd"]).unwrap();
        let s = outs.dir("--slices", &d.join("s")).unwrap();
        outs.write(o, |w| w.write_all(b"first, longer than the second"))
            .unwrap();
        outs.write(o, |w| w.write_all(b"new")).unwrap();
        outs.write_in(s, "z0.png", |w| w.write_all(b"new slice"))
            .unwrap();
        outs.commit().unwrap();
        sync_outputs(false);
        assert_eq!(std::fs::read(&a).unwrap(), b"new", "sync {sync}");
        assert_eq!(std::fs::read(&link).unwrap(), b"old bytes");
        let mode = std::fs::metadata(&a).unwrap().permissions().mode() & 0o777;
        assert_eq!(mode, 0o640);
        assert_eq!(std::fs::read(d.join("s/z0.png")).unwrap(), b"new slice");
        assert_eq!(names(d), ["a.nrrd", "old-link", "s"]);
        assert_eq!(names(&d.join("s")), ["z0.png"]);
    }
}
