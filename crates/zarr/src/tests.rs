use super::*;

fn grid(dims: [usize; 3]) -> Grid {
    // Odd corners and sizes: their decimals must come back exactly.
    Grid::new(
        dims,
        DVec3::new(-1.1, 0.3, 2.0 / 3.0),
        DVec3::new(7.7, 9.1, 5.0),
    )
    .unwrap()
}

fn attrs() -> VolumeAttrs {
    VolumeAttrs::new("test", "codes")
}

fn unsharded(chunk: [usize; 3]) -> Layout {
    Layout {
        chunk,
        shard: 1,
        levels: Some(1),
    }
}

fn sharded(chunk: [usize; 3], shard: usize, levels: usize) -> Layout {
    Layout {
        chunk,
        shard,
        levels: Some(levels),
    }
}

proptest::proptest! {
    /// Every file (shard, or chunk when unsharded) of every level lies in one tile,
    /// scaled back to level 0, and tiles start on voxels even at every level.
    #[test]
    fn a_tile_holds_whole_files_of_every_level(
        dims in proptest::array::uniform3(1usize..600),
        chunk in proptest::array::uniform3(1usize..70),
        shard in 1usize..9,
        levels in 1usize..8,
    ) {
        let layout = Layout { chunk, shard, levels: None };
        let mut levels_of = plan(dims, &layout).unwrap();
        levels_of.truncate(levels);
        let [tx, ty] = tile(dims, &levels_of);
        for (l, v) in levels_of.iter().enumerate() {
            let [_, uy, ux] = v.grid_unit();
            for (t, u, n) in [(tx, ux, dims[0]), (ty, uy, dims[1])] {
                // A tile is the whole side, or a whole number of the level's files.
                proptest::prop_assert!(t == n || (t % (u << l) == 0), "{t} {u} {l} {n}");
                proptest::prop_assert!(t == n || t % (1 << (levels_of.len() - 1)) == 0);
            }
        }
    }
}

#[test]
fn shards_cover_the_same_scene_at_every_level() {
    let levels = plan([4096, 4096, 4096], &Layout::default()).unwrap();
    assert_eq!(levels.len(), 5);
    for (l, v) in levels.iter().enumerate() {
        let [_, sy, sx] = v.shard.unwrap();
        assert_eq!([sy << l, sx << l], [4096, 4096], "level {l}");
    }
    assert_eq!(tile([4096, 4096, 4096], &levels), [4096, 4096]);
    assert_eq!(
        tile(
            [16384, 16384, 16384],
            &plan([16384; 3], &Layout::default()).unwrap()
        ),
        [4096, 4096]
    );
    let small = Layout {
        shard: 8,
        ..Layout::default()
    };
    assert_eq!(
        tile([16384; 3], &plan([16384; 3], &small).unwrap()),
        [4096, 4096]
    );
    let small = Layout {
        shard: 8,
        levels: Some(4),
        ..Layout::default()
    };
    assert_eq!(
        tile([16384; 3], &plan([16384; 3], &small).unwrap()),
        [512, 512]
    );
}

#[test]
fn chunks_are_cut_to_the_grid_and_rows_cover_every_slab_once() {
    assert_eq!(chunk_shape([10, 20, 30], [64, 8, 64]).unwrap(), [30, 8, 10]);
    assert_eq!(
        chunk_shape([10, 20, 30], [4, 0, 4]).unwrap_err(),
        Error::BadChunk { chunk: [4, 0, 4] }
    );
    let dir = tempfile::tempdir().unwrap();
    let v = ZarrVolume::create(
        &dir.path().join("a"),
        &grid([5, 6, 11]),
        &unsharded([4, 4, 4]),
        &attrs(),
    )
    .unwrap();
    assert_eq!(v.chunk(), [4, 4, 4]);
    assert_eq!(v.chunk_rows(), [0..4, 4..8, 8..11]);
    assert_eq!(v.row_bytes(), 4 * 6 * 5);
}

/// The levels and shards of the rule (docs/zarr.md): depth halved per level, sides cut
/// to each level, shards a whole number of chunks, halved per level, cut to the level.
#[test]
fn the_plan_halves_levels_and_cuts_shards() {
    let p = plan([1000, 300, 130], &sharded([64, 64, 64], 4, 3)).unwrap();
    assert_eq!(
        p,
        [
            Level {
                dims: [1000, 300, 130],
                chunk: [64, 64, 64],
                shard: Some([64, 256, 256])
            },
            Level {
                dims: [500, 150, 65],
                chunk: [32, 64, 64],
                shard: Some([32, 128, 128])
            },
            Level {
                dims: [250, 75, 33],
                chunk: [16, 64, 64],
                shard: Some([16, 64, 64])
            },
        ]
    );
    // Level l's shard is 4 >> l chunks a side: each covers a level-0 shard's scene.
    assert_eq!(p[0].files_per_row(), 2 * 4);
    assert_eq!(p[1].files_per_row(), 2 * 4);
    assert_eq!(p[2].files_per_row(), 2 * 4);
    // Defaults: levels until the largest side is at most 256, within the depth's halvings.
    assert_eq!(default_levels([384; 3]), 2);
    assert_eq!(default_levels([256, 10, 10]), 1);
    assert_eq!(default_levels([4096; 3]), 5);
    assert_eq!(default_levels([16384; 3]), 7);
    assert_eq!(default_levels([32768; 3]), 8);
    assert_eq!(max_levels([32768; 3], [64; 3]), 7);
    assert_eq!(max_levels([100, 100, 100], [12, 64, 64]), 3);
    // One row: any depth halves; no level past 1×1×1.
    assert_eq!(max_levels([5, 3, 7], [7, 3, 5]), 4);
    let one = plan([5, 3, 7], &sharded([64; 3], 2, 4)).unwrap();
    assert_eq!(one[3].dims, [1, 1, 1]);
    assert_eq!(one[3].chunk, [1, 1, 1]);
    assert_eq!(one[1].chunk, [4, 2, 3]);
    let l = plan([100, 100, 100], &Layout::new([12, 64, 64])).unwrap();
    assert_eq!(l.len(), 1, "100 ≤ 256: no pyramid by default");
    assert_eq!(
        plan([100, 100, 100], &sharded([12, 64, 64], 64, 4)).unwrap_err(),
        Error::BadLevels {
            levels: 4,
            max: 3,
            depth: 12
        }
    );
    assert_eq!(
        plan([9; 3], &sharded([3; 3], 0, 1)).unwrap_err(),
        Error::BadShard
    );
    assert!(plan([9; 3], &sharded([3; 3], 2, 0)).is_err());
    // Unsharded: no shard at any level.
    let u = plan(
        [300, 20, 20],
        &Layout {
            shard: 1,
            ..Layout::new([4; 3])
        },
    )
    .unwrap();
    assert_eq!(u.len(), 2);
    assert!(u.iter().all(|v| v.shard.is_none()));
}

/// Voxel (i, j, k) is element [k, j, i]; rows written in any order, edge chunks cut;
/// sharded and not.
#[test]
fn a_row_lands_at_k_j_i() {
    let [nx, ny, nz] = [5, 6, 7];
    let value = |i: usize, j: usize, k: usize| (1 + i + 10 * j + 100 * k) as u8;
    for (layout, file) in [
        (unsharded([3, 4, 2]), "0/c/2/1/2"),     // 3 rows of 2 × 3 chunks
        (sharded([3, 4, 2], 2, 1), "0/c/2/0/1"), // shards of 2 × 2 chunks: 1 × 2
    ] {
        let dir = tempfile::tempdir().unwrap();
        let v = ZarrVolume::create(
            &dir.path().join("a"),
            &grid([nx, ny, nz]),
            &layout,
            &attrs(),
        )
        .unwrap();
        for (row, slabs) in v.chunk_rows().into_iter().enumerate().rev() {
            let mut slices = vec![];
            for k in slabs {
                for j in 0..ny {
                    slices.extend((0..nx).map(|i| value(i, j, k)));
                }
            }
            v.write_row(row, &slices).unwrap();
        }
        let all = v.read_level(0).unwrap();
        for k in 0..nz {
            for j in 0..ny {
                for i in 0..nx {
                    assert_eq!(
                        all[(k * ny + j) * nx + i],
                        value(i, j, k),
                        "{layout:?} ({i}, {j}, {k})"
                    );
                }
            }
        }
        assert!(dir.path().join("a").join(file).is_file(), "{layout:?}");
        let files = v.files_written();
        assert_eq!(
            files,
            [v.levels()[0].files_per_row() as u64 * 3],
            "{layout:?}"
        );
    }
}

/// A chunk that becomes all 0 loses its file (sharded: its index entry, then its shard's
/// file); the rest read as 0 without one.
#[test]
fn all_zero_chunks_have_no_file() {
    for layout in [unsharded([2, 4, 2]), sharded([2, 4, 2], 2, 1)] {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("a");
        let v = ZarrVolume::create(&path, &grid([4, 4, 4]), &layout, &attrs()).unwrap();
        let mut row = vec![0u8; 2 * 4 * 4];
        row[3] = 9; // voxel (3, 0, 0): chunk (0, 0, 1)
        v.write_row(0, &row).unwrap();
        let (kept, gone) = match layout.shard {
            1 => ("0/c/0/0/1", "0/c/0/0/0"),
            _ => ("0/c/0/0/0", "0/c/1/0/0"),
        };
        assert!(path.join(kept).is_file(), "{layout:?}");
        assert!(!path.join(gone).exists(), "{layout:?}");
        if layout.shard > 1 {
            // One inner chunk of two, and a 2-entry index: (offset 0, its length) and
            // (MAX, MAX) for the empty one.
            let bytes = std::fs::read(path.join(kept)).unwrap();
            let index: Vec<u64> = bytes[bytes.len() - 32..]
                .chunks(8)
                .map(|b| u64::from_le_bytes(b.try_into().unwrap()))
                .collect();
            assert_eq!(index[..2], [u64::MAX, u64::MAX]);
            assert_eq!(index[2..], [0, bytes.len() as u64 - 32]);
        }
        assert_eq!(v.read_level(0).unwrap()[3], 9);
        v.write_row(0, &[0; 32]).unwrap();
        assert!(!path.join(kept).exists(), "{layout:?}");
        assert!(v.read_level(0).unwrap().iter().all(|&x| x == 0));
    }
}

/// Unsharded chunks, written here rather than by zarrs's store (which syncs each file),
/// are the bytes zarrs's own chunk writer gives for the same chunks.
#[test]
fn unsharded_chunks_are_the_bytes_zarrs_writes() {
    let dir = tempfile::tempdir().unwrap();
    let layout = unsharded([2, 3, 2]);
    let (ours, theirs) = (dir.path().join("ours"), dir.path().join("theirs"));
    let v = ZarrVolume::create(&ours, &grid([5, 4, 2]), &layout, &attrs()).unwrap();
    let z = ZarrVolume::create(&theirs, &grid([5, 4, 2]), &layout, &attrs()).unwrap();
    // A mixed chunk, a chunk of one value, chunks cut by the grid's edges, empty ones.
    let row: Vec<u8> = (0..40u8)
        .map(|i| [0, 7, i % 3, 7][(i / 10) as usize])
        .collect();
    v.write_row(0, &row).unwrap();
    let cut = shard::RowCut {
        slices: &row,
        nx: 5,
        ny: 4,
        slabs: 2,
        chunk: [2, 3, 2],
        at: [0, 0],
        known: None,
    };
    let (down, across) = cut.grid();
    let mut files = 0;
    for (j, i) in (0..down).flat_map(|j| (0..across).map(move |i| (j, i))) {
        let key = format!("0/c/0/{j}/{i}");
        if cut.held(j, i) == shard::Held::Empty {
            assert!(!ours.join(&key).exists(), "{key}");
            continue;
        }
        let chunk = cut.copy(j, i);
        let options = zarrs::array::CodecOptions::default();
        let at = [0, j as u64, i as u64];
        z.levels[0]
            .array
            .store_chunk_opt(&at, chunk, &options)
            .unwrap();
        let (a, b) = (ours.join(&key), theirs.join(&key));
        assert_eq!(
            std::fs::read(a).unwrap(),
            std::fs::read(b).unwrap(),
            "{key}"
        );
        files += 1;
    }
    assert!(files >= 3, "{files}");
}

/// Each level read back is the downsample of the one below, and is placed at the centre
/// of the voxels it covers.
#[test]
fn levels_are_downsamples_of_the_level_below() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("a");
    let [nx, ny, nz] = [13, 9, 11];
    let g = grid([nx, ny, nz]);
    let v = ZarrVolume::create(&path, &g, &sharded([4, 4, 4], 2, 3), &attrs()).unwrap();
    assert_eq!(v.chunk_rows().len(), 3);
    let value = |i: usize, j: usize, k: usize| ((i * 7 + j * 3 + k) % 5) as u8;
    for (row, slabs) in v.chunk_rows().into_iter().enumerate() {
        let mut slices = vec![];
        for k in slabs {
            for j in 0..ny {
                slices.extend((0..nx).map(|i| value(i, j, k)));
            }
        }
        v.write_row(row, &slices).unwrap();
    }
    let mut want = v.read_level(0).unwrap();
    let mut dims = [nx, ny, nz];
    for l in 1..3 {
        want = downsample(&want, dims);
        dims = dims.map(|d| d.div_ceil(2));
        assert_eq!(v.levels()[l].dims, dims);
        assert_eq!(v.read_level(l).unwrap(), want, "level {l}");
    }
    let group: Value =
        serde_json::from_slice(&std::fs::read(path.join("zarr.json")).unwrap()).unwrap();
    let ds = &group["attributes"]["ome"]["multiscales"][0]["datasets"];
    let t = &ds[2]["coordinateTransformations"];
    let (o, s) = (g.centre(0, 0, 0), g.voxel());
    assert_eq!(ds[2]["path"], "2");
    assert_eq!(t[0]["scale"], json!(zyx(s * 4.0)));
    // Level 2's voxel 0 covers level 0's 0..4: its centre is 1.5 voxels past theirs.
    assert_eq!(t[1]["translation"], json!(zyx(o + s * 1.5)));
    let reopened = ZarrVolume::open(&path).unwrap();
    assert_eq!(reopened.levels(), v.levels());
    assert_eq!(reopened.layout(), sharded([4, 4, 4], 2, 3));
}

#[test]
fn open_gives_back_the_grid_exactly_and_refuses_other_stores() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("a");
    let g = grid([9, 8, 7]);
    ZarrVolume::create(&path, &g, &Layout::new([5, 5, 5]), &attrs()).unwrap();
    let v = ZarrVolume::open(&path).unwrap();
    assert_eq!((*v.grid(), v.chunk(), v.dims()), (g, [5, 5, 5], [9, 8, 7]));
    assert_eq!(v.shard(), DEFAULT_SHARD);

    // A Zarr group that is not ours.
    let foreign = dir.path().join("b");
    std::fs::create_dir(&foreign).unwrap();
    std::fs::write(
        foreign.join("zarr.json"),
        r#"{"zarr_format": 3, "node_type": "group", "attributes": {}}"#,
    )
    .unwrap();
    let e = ZarrVolume::open(&foreign).unwrap_err().to_string();
    assert!(
        e.ends_with("not a csgpix Zarr volume: no `csgpix` attribute"),
        "{e}"
    );
    // Ours with its array gone.
    std::fs::remove_file(path.join("0/zarr.json")).unwrap();
    let e = ZarrVolume::open(&path).unwrap_err().to_string();
    assert!(e.contains("not a csgpix Zarr volume"), "{e}");
    // create: only where nothing is.
    let e = ZarrVolume::create(&path, &g, &Layout::new([5, 5, 5]), &attrs()).unwrap_err();
    assert_eq!(e, Error::NotEmpty { path: path.clone() });
    let file = dir.path().join("f");
    std::fs::write(&file, b"x").unwrap();
    let e = ZarrVolume::create(&file, &g, &Layout::new([5, 5, 5]), &attrs()).unwrap_err();
    assert_eq!(e, Error::NotEmpty { path: file });

    // An array whose shards are not what the attribute says.
    let c = dir.path().join("c");
    ZarrVolume::create(&c, &g, &sharded([2, 2, 2], 2, 1), &attrs()).unwrap();
    let meta = c.join("0/zarr.json");
    let mut m: Value = serde_json::from_slice(&std::fs::read(&meta).unwrap()).unwrap();
    assert_eq!(
        m["chunk_grid"]["configuration"]["chunk_shape"],
        json!([2, 4, 4])
    );
    m["chunk_grid"]["configuration"]["chunk_shape"] = json!([2, 2, 4]);
    std::fs::write(&meta, m.to_string()).unwrap();
    let e = ZarrVolume::open(&c).unwrap_err().to_string();
    assert!(e.contains("level 0: `chunk_grid` is"), "{e}");
}

#[test]
fn bad_rows_are_refused_in_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let v = ZarrVolume::create(
        &dir.path().join("a"),
        &grid([2, 3, 5]),
        &Layout::new([4, 3, 2]),
        &attrs(),
    )
    .unwrap();
    assert_eq!(
        v.write_row(2, &[]).unwrap_err().to_string(),
        "chunk row 2: the volume has rows 0..2"
    );
    assert_eq!(
        v.write_row(1, &[1; 7]).unwrap_err().to_string(),
        "chunk row 1: expected 6 bytes (slabs 1 of 2x3), got 7"
    );
}

/// The writer's estimate grows with the rows and the chunk, not with the shard.
#[test]
fn the_writers_estimate() {
    let d = [2048, 2048, 2048];
    let s = |shard| {
        writer_bytes(
            d,
            &Layout {
                shard,
                ..Layout::default()
            },
            2,
        )
        .unwrap()
    };
    // A shard costs its index alone, 16 bytes a chunk (64 is cut to the grid's 32).
    assert_eq!(s(64) - s(16), 2 * 16 * (32 * 32 - 16 * 16));
    let row0 = 64 * 2048 * 2048u64;
    assert!(s(64) > row0 + row0 / 8 && s(64) < row0 + row0 / 7 + (8 << 20));
    assert!(s(1) > row0 + 8 * (64 << 12));
}
