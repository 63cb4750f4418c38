//! Statements read with an explicit stack of open nodes, and what each node gives its parent.

use glam::DVec3;

use crate::extrude::{
    convex_prism, flatten, linear_mesh, map_region, region_bytes, rotate_mesh, Linear, Poly2,
    Region,
};
use crate::geom::{leaf_mesh, minkowski2, minkowski3, pieces2, Piece, Piece2};
use crate::hull::hull3;
use crate::memo::{MeshMemo, Solid};
use crate::pieces::pieces;
use crate::{
    consts_::*,
    flat::*,
    frame::*,
    import::*,
    lex::*,
    linalg::*,
    node::*,
    primitives::*,
    project::{move_leaves, projection, resize},
    transform::*,
    tree::*,
    value::*,
};
use crate::{Fallback, ReadOptions};
use csgpix_scene::footprint::{keeps_z, Footprint, Op as FootOp};
use csgpix_scene::solid::{ConvexSolid, CsgNode, CsgScene, Import, IMPORTED};
use csgpix_scene::{CsgError, Error};

/// An `import` of a DXF file, which `--fallback openscad` outlines when csgpix refuses it
/// (`.svg` and `.dxf` are read natively, modules [`crate::svg`] and [`crate::dxf`]).
fn flat_import(head: &Head) -> bool {
    head.kind == NodeKind::Import
        && head.params.get("file").is_some_and(|v| match &v.kind {
            Kind::Str(f) => f.to_ascii_lowercase().ends_with(".dxf"),
            _ => false,
        })
}

/// What comes next at a statement position.
pub(crate) enum Next {
    Eof,
    CloseBrace,
    Semicolon,
    Statement,
}

pub(crate) struct Reader<'a> {
    pub(crate) text: &'a str,
    pub(crate) options: &'a ReadOptions,
    pub(crate) parser: Parser<'a>,
    pub(crate) solids: Vec<ConvexSolid>,
    /// Leaves `Solid(IMPORTED + j)` until the end, when they become `Solid(solids + j)`.
    pub(crate) imports: Vec<Import>,
    pub(crate) vertices: usize,
    pub(crate) open: Vec<Frame>,
    pub(crate) top: Vec<CsgNode>,
    /// Solids and imports a `hull()` took in: they leave the scene at the end.
    pub(crate) consumed_solids: Vec<usize>,
    pub(crate) consumed_imports: Vec<usize>,
    /// 2D shapes at the top level (ignored beside solids), the first one's position.
    pub(crate) top_flat: Option<Pos>,
    /// The top level's dimension: its first object's that is not empty, as OpenSCAD's root
    /// takes it (`GeometryEvaluator::applyToChildren`).
    pub(crate) top_dim: Option<Dim>,
    /// Warnings as OpenSCAD gives them, with where they arose.
    pub(crate) warnings: Vec<(Pos, String)>,
    /// What drawing the scene's text held at most, in bytes ([`CsgScene::reading_bytes`]).
    drawing_bytes: u64,
    /// The most bytes one extrusion's 2D outlines held until it was made
    /// ([`CsgScene::reading_bytes`]).
    flat_bytes: u64,
    /// The scene's own fonts ([`ReadOptions::fonts`]) before the standard ones, loaded at the
    /// first `text()`; this scene's alone.
    pub(crate) scene_fonts: std::cell::OnceCell<crate::text::Fonts>,
    /// Each `minkowski()` of solids summed so far, by its text (runs of white space as one
    /// space: a module called again gives the same statement, indented by its depth), whose
    /// sum in its own coordinates is the same (the sum is placed after, [`Self::minkowski3`]).
    sums: std::collections::HashMap<String, Sum>,
    /// Each `offset()`'s outline in its own coordinates, by its text as [`Self::sums`].
    outlines: std::collections::HashMap<String, Region>,
    /// The bytes [`Self::sums`] and [`Self::outlines`] hold ([`CsgScene::reading_bytes`]).
    kept_bytes: u64,
    /// The meshes of the booleans evaluated so far ([`MeshMemo`]).
    pub(crate) meshes: MeshMemo,
    /// The `text()`s drawn so far ([`crate::text::Drawn`]).
    texts: crate::text::Drawn,
}

/// A `minkowski()`'s sum in its own coordinates, as the scene's solids and meshes (without
/// their colour and line, which are each statement's), and the vertices the budget had to
/// hold for it ([`crate::geom::minkowski3`]'s count, the most of any step of the fold).
struct Sum {
    parts: Vec<SumPart>,
    need: usize,
}

/// One piece of a sum, made: a convex solid (its hull taken) or a closed mesh.
enum SumPart {
    Convex(ConvexSolid),
    Mesh(std::sync::Arc<Vec<[[f64; 3]; 3]>>),
}

impl Sum {
    /// The pieces made, in order: each convex piece the solid of its hull (taken when the
    /// piece was summed), each mesh its triangles.
    fn of(pieces: Vec<Piece>, need: usize) -> Sum {
        let parts = pieces
            .into_iter()
            .map(|p| match p {
                Piece::Convex(p) => SumPart::Convex(p.solid(None, 0)),
                Piece::Mesh(m) => SumPart::Mesh(std::sync::Arc::new(
                    m.iter().map(|t| t.map(|v| v.to_array())).collect(),
                )),
            })
            .collect();
        Sum { parts, need }
    }

    fn bytes(&self) -> u64 {
        let vertex = std::mem::size_of::<[f64; 3]>() as u64;
        self.parts
            .iter()
            .map(|p| match p {
                SumPart::Convex(s) => {
                    let indices: usize = s.faces.iter().map(|f| f.len() + 1).sum();
                    s.vertices.len() as u64 * vertex + indices as u64 * 4
                }
                SumPart::Mesh(m) => m.len() as u64 * 3 * vertex,
            })
            .sum()
    }
}

impl<'a> Reader<'a> {
    /// The most vertices the scene may have ([`ReadOptions::max_vertices`]).
    pub(crate) fn max_vertices(&self) -> usize {
        self.options.max_vertices.unwrap_or(MAX_SCENE_VERTICES)
    }

    pub(crate) fn new(text: &'a str, options: &'a ReadOptions) -> Self {
        Reader {
            text,
            options,
            parser: Parser::new(text),
            solids: Vec::new(),
            imports: Vec::new(),
            vertices: 0,
            open: Vec::new(),
            top: Vec::new(),
            consumed_solids: Vec::new(),
            consumed_imports: Vec::new(),
            top_flat: None,
            top_dim: None,
            warnings: Vec::new(),
            drawing_bytes: 0,
            flat_bytes: 0,
            scene_fonts: std::cell::OnceCell::new(),
            meshes: MeshMemo::default(),
            texts: Default::default(),
            sums: std::collections::HashMap::new(),
            outlines: std::collections::HashMap::new(),
            kept_bytes: 0,
        }
    }

    /// The fonts `text()` looks in: the scene's own font files first, when it has any.
    pub(crate) fn fonts(&self) -> &crate::text::Fonts {
        if self.options.fonts.is_empty() {
            return crate::text::Fonts::standard();
        }
        self.scene_fonts
            .get_or_init(|| crate::text::Fonts::scene(&self.options.fonts))
    }

    pub(crate) fn run(mut self) -> Result<CsgScene, Fail> {
        loop {
            let token = self.parser.peek()?;
            let pos = token.pos;
            let next = match token.tok {
                Tok::Eof => Next::Eof,
                Tok::Sym(b'}') => Next::CloseBrace,
                Tok::Sym(b';') => Next::Semicolon,
                _ => Next::Statement,
            };
            match next {
                Next::Eof => return self.end(pos),
                Next::CloseBrace => self.close_brace(pos)?,
                Next::Semicolon => {
                    self.parser.next()?;
                    self.empty_statement()?;
                }
                Next::Statement => self.statement(pos)?,
            }
        }
    }

    fn end(mut self, pos: Pos) -> Result<CsgScene, Fail> {
        match self.open.pop() {
            None => {
                let mut root = combine(Op::Union, std::mem::take(&mut self.top));
                if let Some(at) = self.top_flat {
                    if self.top_dim == Some(Dim::Flat) && root != CsgNode::Empty {
                        return fail(at, CsgError::FlatTopLevel { alone: false });
                    }
                    if root == CsgNode::Empty {
                        return fail(at, CsgError::FlatTopLevel { alone: true });
                    }
                    let msg = "Ignoring 2D child object for 3D operation (top level)";
                    self.warnings.push((at, msg.to_string()));
                }
                let (solids, imports) = self.drop_consumed(&mut root);
                root.number_imports_after(solids.len());
                let warnings = self
                    .warnings
                    .iter()
                    .map(|(at, msg)| {
                        let message = msg.clone();
                        Error::at("", at.line, at.col, Error::Warning { message })
                    })
                    .collect();
                Ok(CsgScene {
                    solids,
                    imports,
                    root,
                    warnings,
                    reading_bytes: self
                        .drawing_bytes
                        .saturating_add(self.flat_bytes)
                        .saturating_add(self.kept_bytes)
                        .saturating_add(self.texts.bytes)
                        .saturating_add(self.meshes.bytes()),
                })
            }
            Some(frame) => fail(pos, unclosed(&frame, "end of file")),
        }
    }

    fn close_brace(&mut self, pos: Pos) -> Result<(), Fail> {
        match self.open.last() {
            None => fail(pos, CsgError::UnexpectedCloseBrace),
            Some(frame) if frame.closer == Closer::Single => fail(pos, unclosed(frame, "'}'")),
            Some(_) => {
                self.parser.next()?;
                let node = self.pop_and_finish()?;
                self.deliver(node)
            }
        }
    }

    /// A lone `;`: nothing inside braces, no children after `group()`.
    fn empty_statement(&mut self) -> Result<(), Fail> {
        if self.open.last().is_some_and(|f| f.closer == Closer::Single) {
            let node = self.pop_and_finish()?;
            self.deliver(node)?;
        }
        Ok(())
    }

    fn statement(&mut self, pos: Pos) -> Result<(), Fail> {
        if self.open.len() >= MAX_NESTING {
            let problem = CsgError::NestedTooDeep {
                what: "statements",
                limit: MAX_NESTING,
            };
            return fail(pos, problem);
        }
        if self.options.fallback == Fallback::Openscad {
            if let Some(name) = self.unknown_node()? {
                let parent = self.open.last().map(|f| f.ctx.clone()).unwrap_or_default();
                let node = self.fallback(&name, pos, &parent)?;
                return self.deliver(node);
            }
        }
        let start = self.parser.peek()?.span.0;
        let head = self.head()?;
        let parent = self.open.last().map(|f| f.ctx.clone()).unwrap_or_default();
        let ctx = child_ctx(&parent, &head, &mut self.warnings)?;
        if head.kind.is_leaf() {
            let context = format!("after `{}(…)` (it takes no children)", head.kind.name());
            self.parser.expect_sym(b';', &context)?;
            if self.options.fallback == Fallback::Openscad && flat_import(&head) {
                let source = &self.text[start..self.parser.last_end];
                let node = self.dxf(&head, &ctx, Some(source))?;
                return self.deliver(node);
            }
            let node = self.leaf(&head, &ctx)?;
            return self.deliver(node);
        }
        let closer = match self.parser.eat_sym(b'{')? {
            Some(brace) => Closer::Brace(brace),
            None => Closer::Single,
        };
        let spec = flat_spec(&head)?;
        let mut ctx = ctx;
        let placement = match head.kind {
            // Their children start from the identity: the result is placed afterwards (an
            // offset's distance is in its own coordinates, which a scale above it changes; a
            // Minkowski sum is made where OpenSCAD makes it, and kept by its text).
            NodeKind::LinearExtrude
            | NodeKind::RotateExtrude
            | NodeKind::Projection
            | NodeKind::Resize
            | NodeKind::Offset
            | NodeKind::Minkowski => ctx.matrix.take(),
            _ => None,
        };
        self.open.push(Frame {
            kind: head.kind,
            closer,
            ctx,
            children: Vec::new(),
            flats: Vec::new(),
            first_flat: None,
            dim: match head.kind {
                NodeKind::LinearExtrude | NodeKind::RotateExtrude | NodeKind::Offset => {
                    Some(Dim::Flat)
                }
                _ => None,
            },
            pos: head.pos,
            spec,
            placement,
            start,
        });
        Ok(())
    }

    /// Modifiers, name and arguments of a statement.
    fn head(&mut self) -> Result<Head, Fail> {
        let mut skip = false;
        let token = loop {
            let token = self.parser.next()?;
            match token.tok {
                Tok::Sym(b'%' | b'*') => skip = true,
                Tok::Sym(b'#') => {}
                Tok::Sym(b'!') => return fail(token.pos, CsgError::RootModifier),
                _ => break token,
            }
        };
        let Tok::Ident(name) = &token.tok else {
            let expected = "a statement such as `group() {`";
            return fail(token.pos, expected_found(expected, &token.tok));
        };
        let Some(kind) = NodeKind::from_name(name) else {
            return fail(token.pos, unsupported(name));
        };
        let args = self.parser.args(name)?;
        let params = Params::bind(kind, token.pos, args)?;
        Ok(Head {
            kind,
            pos: token.pos,
            params,
            skip,
        })
    }

    /// Hands a finished node (or nothing, for a skipped one) to the open operation, closing
    /// the single-child operations it completes. A child of the other dimension than the
    /// operation's is ignored with OpenSCAD's warning (its leaves leave the scene); a 2D
    /// shape at the top level is ignored beside solids and refused alone ([`Self::end`]).
    fn deliver(&mut self, mut node: Option<Item>) -> Result<(), Fail> {
        loop {
            let Some(frame) = self.open.last_mut() else {
                match node {
                    Some(Item::Flat(_, pos)) => {
                        self.top_flat.get_or_insert(pos);
                        self.top_dim.get_or_insert(Dim::Flat);
                    }
                    Some(Item::Solid(n)) => {
                        if n != CsgNode::Empty {
                            self.top_dim.get_or_insert(Dim::Solid);
                        }
                        self.top.push(n)
                    }
                    None => {}
                }
                return Ok(());
            };
            let pos = frame.pos;
            match (node, frame.dim) {
                (Some(Item::Solid(CsgNode::Empty)), Some(Dim::Flat)) => {}
                (Some(Item::Solid(n)), Some(Dim::Flat)) => {
                    // OpenSCAD's collectChildren2D puts an empty geometry in its place, which
                    // empties an intersection.
                    if frame.kind == NodeKind::Intersection {
                        frame.flats.push(Region::Union(vec![]));
                    }
                    self.ignore(pos, "Ignoring 3D child object for 2D operation", &n);
                }
                (Some(Item::Solid(n)), _) => {
                    if !matches!(n, CsgNode::Empty) {
                        frame.dim = Some(Dim::Solid);
                    }
                    frame.children.push(n);
                }
                (Some(Item::Flat(_, _)), Some(Dim::Solid)) => {
                    // collectChildren3D: an empty geometry in its place.
                    if frame.kind == NodeKind::Intersection {
                        frame.children.push(CsgNode::Empty);
                    }
                    let msg = "Ignoring 2D child object for 3D operation".to_string();
                    self.warnings.push((pos, msg));
                }
                (Some(Item::Flat(r, at)), _) => {
                    frame.dim = Some(Dim::Flat);
                    frame.flats.push(r);
                    frame.first_flat.get_or_insert(at);
                }
                (None, _) => {}
            }
            let Some(frame) = self.open.last() else {
                return Ok(());
            };
            if frame.closer != Closer::Single {
                return Ok(());
            }
            node = self.pop_and_finish()?;
        }
    }

    /// Closes the innermost open operation: what it gives its parent (nothing when skipped).
    fn pop_and_finish(&mut self) -> Result<Option<Item>, Fail> {
        let Some(frame) = self.open.pop() else {
            return Ok(None);
        };
        if frame.ctx.skip {
            return Ok(None);
        }
        let (kind, pos) = (frame.kind, frame.pos);
        let flat_at = frame.first_flat.unwrap_or(pos);
        if kind.needs_geometry() {
            self.read_imported_meshes(&frame.children)?;
        }
        match kind {
            NodeKind::LinearExtrude | NodeKind::RotateExtrude => self.extrude(frame).map(Some),
            NodeKind::Hull if frame.flats.is_empty() => self.hull3(frame).map(Some),
            NodeKind::Hull => hull_flat(frame),
            NodeKind::Minkowski if frame.flats.is_empty() => self.minkowski3(frame).map(Some),
            NodeKind::Minkowski => self.minkowski2(frame),
            NodeKind::Offset => self.offset(frame),
            NodeKind::Projection => {
                let (item, below) =
                    projection(frame, &self.solids, &self.imports, &mut self.meshes)?;
                self.consume(&below);
                Ok(Some(item))
            }
            NodeKind::Resize => {
                if let Spec::Resize { newsize, .. } = frame.spec {
                    if newsize.iter().any(|&s| s < 0.0) {
                        let msg = "resize() with a negative size: ignored for a primitive or a \
                                   2D shape, a mirror for a boolean's result, as OpenSCAD 2021.01 \
                                   renders them";
                        self.warnings.push((pos, msg.to_string()));
                    }
                }
                resize(frame, &mut self.solids, &mut self.imports, &mut self.meshes).map(Some)
            }
            _ if frame.dim == Some(Dim::Flat) => {
                Ok(Some(Item::Flat(region_of(kind.op(), frame.flats), flat_at)))
            }
            _ => Ok(Some(Item::Solid(combine(kind.op(), frame.children)))),
        }
    }

    /// Reads now the mesh files imported below an operation that needs their geometry while
    /// the scene is read ([`NodeKind::needs_geometry`]), as OpenSCAD's importer gives every
    /// `import()` its mesh at once: relative to the scene's folder, placed by the import's
    /// matrix, with the reading's warnings and an open mesh's at the `import`. Without a folder
    /// (a scene given as text) they stay files, which those operations refuse; datasets stay
    /// files.
    fn read_imported_meshes(&mut self, below: &[CsgNode]) -> Result<(), Fail> {
        let Some(dir) = self.options.dir.clone() else {
            return Ok(());
        };
        let leaves = below.iter().flat_map(crate::project::leaves);
        for i in leaves.filter_map(|i| i.checked_sub(IMPORTED)) {
            let import = &self.imports[i];
            if import.mesh.is_some() || import.footprint.is_some() || import.threshold.is_some() {
                continue;
            }
            let pos = Pos {
                line: import.line,
                col: import.col,
            };
            let path = dir.join(&import.file);
            let (mesh, found) = csgpix_scene::trimesh::TriMesh::read_with_warnings(&path)
                .map_err(|problem| Fail { pos, problem })?;
            let m = import.matrix.unwrap_or(IDENTITY);
            let tris: Vec<[Vec3; 3]> = (mesh.triangles.iter())
                .map(|t| t.map(|v| transform_point(&m, mesh.vertices[v as usize].to_array())))
                .collect();
            let open = mesh.open_edges_summary(&import.file).ok().flatten();
            let file = import.file.clone();
            self.imports[i].mesh = Some(std::sync::Arc::new(tris));
            self.imports[i].matrix = None;
            self.warnings
                .extend(found.into_iter().map(|w| (pos, w.to_string())));
            if let Some(what) = open {
                let msg = format!(
                    "`{file}`: mesh is not closed: {what}; OpenSCAD's render drops it, csgpix \
                     uses its triangles as they are"
                );
                self.warnings.push((pos, msg));
            }
        }
        Ok(())
    }

    /// The name of the statement ahead when csgpix does not read that node.
    fn unknown_node(&mut self) -> Result<Option<String>, Fail> {
        let mut n = 0;
        while matches!(
            self.parser.peek_nth(n)?.tok,
            Tok::Sym(b'%' | b'*' | b'#' | b'!')
        ) {
            n += 1;
        }
        Ok(match &self.parser.peek_nth(n)?.tok {
            Tok::Ident(name) if NodeKind::from_name(name).is_none() => Some(name.clone()),
            _ => None,
        })
    }

    /// `--fallback openscad`: the whole statement (its children included) meshed by openscad
    /// and drawn as a closed mesh primitive under the transform and colour above it.
    fn fallback(&mut self, name: &str, pos: Pos, ctx: &Ctx) -> Result<Option<Item>, Fail> {
        let (start, end, skip) = self.statement_span()?;
        if skip || ctx.skip {
            return Ok(None);
        }
        let source = &self.text[start..end];
        let tris = crate::fallback::mesh(source, self.options).map_err(|e| Fail {
            pos,
            problem: e.context(format_args!("`{name}` (--fallback openscad)")),
        })?;
        let count = tris.len();
        let budget = self.max_vertices().saturating_sub(self.vertices);
        check_budget(count * 3, budget, pos)?;
        self.vertices += count * 3;
        let to = Placement {
            matrix: ctx.matrix,
            colour: ctx.colour,
            pos,
            name: "fallback",
        };
        let node = self.push_mesh(tris, &to)?;
        let msg = format!("`{name}` meshed by openscad (--fallback openscad): {count} triangles");
        self.warnings.push((pos, msg));
        Ok(Some(Item::Solid(node)))
    }

    /// `--fallback openscad` of a 2D import (`.svg`, `.dxf`): openscad's outline of it, as a
    /// 2D shape placed by the transforms above it.
    fn fallback_flat(
        &mut self,
        source: &str,
        head: &Head,
        ctx: &Ctx,
    ) -> Result<Option<Item>, Fail> {
        if ctx.skip {
            return Ok(None);
        }
        let region = crate::fallback::outline(source, self.options).map_err(|e| Fail {
            pos: head.pos,
            problem: e.context("`import` (--fallback openscad)"),
        })?;
        let m = plane_part(ctx.matrix.as_ref());
        let region = map_region(region, &|p| p.transformed(m));
        let msg = "`import` of a 2D file outlined by openscad (--fallback openscad)".to_string();
        self.warnings.push((head.pos, msg));
        Ok(Some(Item::Flat(region, head.pos)))
    }

    /// Consumes one statement whole: its byte range, and whether a `%` or `*` drops it.
    fn statement_span(&mut self) -> Result<(usize, usize, bool), Fail> {
        let first = self.parser.next()?;
        let (start, mut end) = first.span;
        let skip = matches!(first.tok, Tok::Sym(b'%' | b'*'));
        let mut depth = 0usize;
        let mut tok = first.tok;
        loop {
            match tok {
                Tok::Sym(b'(' | b'[' | b'{') => depth += 1,
                Tok::Sym(b')' | b']') => depth = depth.saturating_sub(1),
                Tok::Sym(b'}') => {
                    depth = depth.saturating_sub(1);
                    if depth == 0 {
                        return Ok((start, end, skip));
                    }
                }
                Tok::Sym(b';') if depth == 0 => return Ok((start, end, skip)),
                Tok::Eof => return fail(self.parser.peek()?.pos, CsgError::UnexpectedEof),
                _ => {}
            }
            let t = self.parser.next()?;
            end = t.span.1;
            tok = t.tok;
        }
    }

    /// A child of the wrong dimension: dropped with OpenSCAD's warning, its leaves out of
    /// the scene.
    fn ignore(&mut self, pos: Pos, why: &str, n: &CsgNode) {
        self.warnings.push((pos, why.to_string()));
        let mut stack = vec![n];
        while let Some(n) = stack.pop() {
            match n {
                CsgNode::Solid(i) if *i >= IMPORTED => self.consumed_imports.push(i - IMPORTED),
                CsgNode::Solid(i) => self.consumed_solids.push(*i),
                _ => stack.extend(n.children()),
            }
        }
    }

    /// An object OpenSCAD removes with a warning (`why`; nothing when `None`): the warning
    /// unless the object is skipped anyway, and what it gives its parent: nothing for a 2D
    /// object, an empty solid for a 3D one (which empties an intersection, as OpenSCAD's
    /// empty geometry does).
    fn removed(&mut self, why: Option<&str>, pos: Pos, skip: bool, flat: bool) -> Option<Item> {
        if let (Some(msg), false) = (why, skip) {
            self.warnings.push((pos, msg.to_string()));
        }
        (!skip && !flat).then_some(Item::Solid(CsgNode::Empty))
    }

    /// A primitive of zero, negative or non-finite size: OpenSCAD draws nothing; csgpix says so.
    fn empty_primitive(&mut self, head: &Head, ctx: &Ctx) {
        if !ctx.skip {
            let msg = format!(
                "`{}` has a zero, negative or non-finite size: it is empty",
                head.kind.name()
            );
            self.warnings.push((head.pos, msg));
        }
    }

    /// `import("x.svg")`: the file's shapes (module [`crate::svg`]), placed by the
    /// transforms above.
    fn svg(&mut self, head: &Head, ctx: &Ctx) -> Result<Option<Item>, Fail> {
        let args = crate::import::svg_args(head)?;
        if ctx.skip {
            return Ok(None);
        }
        self.warnings.extend(args.warning.clone());
        let dir = self.options.dir.clone().unwrap_or_default();
        let budget = self.max_vertices().saturating_sub(self.vertices);
        let shapes = crate::svg::read(&dir.join(&args.file), args.dpi, args.center, budget)
            .map_err(|e| Fail {
                pos: head.pos,
                problem: e.context(format_args!("`import(\"{}\")` (an SVG file)", args.file)),
            })?;
        let n: usize = shapes.iter().map(|p| p.points().count()).sum();
        check_budget(n, budget, head.pos)?;
        if let Some(msg) = removal_2d(ctx.matrix.as_ref()) {
            return Ok(self.removed(Some(msg), head.pos, false, true));
        }
        self.vertices += n;
        let m = plane_part(ctx.matrix.as_ref());
        let mut parts: Vec<Region> = shapes
            .into_iter()
            .map(|p| Region::Poly(p.transformed(m)))
            .collect();
        let region = match parts.len() {
            0 => {
                let msg = format!("`import(\"{}\")`: the SVG file draws nothing", args.file);
                self.warnings.push((head.pos, msg));
                return Ok(None);
            }
            1 => parts.pop().expect("one shape"),
            _ => Region::Union(parts),
        };
        Ok(Some(Item::Flat(region, head.pos)))
    }

    /// `import("x.dxf")`: the file's drawing (module [`crate::dxf`]), placed by the
    /// transforms above. A file csgpix refuses is outlined by openscad when `fallback` holds
    /// the statement's text (`--fallback openscad`).
    fn dxf(
        &mut self,
        head: &Head,
        ctx: &Ctx,
        fallback: Option<&str>,
    ) -> Result<Option<Item>, Fail> {
        let args = crate::import::dxf_args(head)?;
        if ctx.skip {
            return Ok(None);
        }
        self.warnings.extend(args.warning.clone());
        let dir = self.options.dir.clone().unwrap_or_default();
        let budget = self.max_vertices().saturating_sub(self.vertices);
        let what = format!("`import(\"{}\")` (a DXF file)", args.file);
        let read = crate::dxf::read(&dir.join(&args.file), &args.file, &args.settings, budget);
        let drawing = match (read, fallback) {
            (Ok(d), _) => d,
            (Err(e), Some(source)) => {
                self.warnings.push((head.pos, format!("{what}: {e}")));
                return self.fallback_flat(source, head, ctx);
            }
            (Err(e), None) => {
                return Err(Fail {
                    pos: head.pos,
                    problem: e.context(what),
                })
            }
        };
        let at = |w: String| (head.pos, w);
        self.warnings.extend(drawing.warnings.into_iter().map(at));
        let n = drawing.shape.points().count();
        check_budget(n, budget, head.pos)?;
        self.vertices += n;
        if drawing.shape.paths.is_empty() {
            let msg = format!("{what}: the DXF file draws nothing");
            self.warnings.push((head.pos, msg));
            return Ok(None);
        }
        if let Some(msg) = removal_2d(ctx.matrix.as_ref()) {
            return Ok(self.removed(Some(msg), head.pos, false, true));
        }
        let m = plane_part(ctx.matrix.as_ref());
        let region = Region::Poly(drawing.shape.transformed(m));
        Ok(Some(Item::Flat(region, head.pos)))
    }

    /// `surface(file, center, invert)`: the heights of a `.dat` grid or a PNG image closed
    /// into a solid (module [`crate::surface`]), a closed mesh primitive placed by the
    /// transforms above. A file OpenSCAD cannot read, or too few heights, is empty, with
    /// OpenSCAD's warning or csgpix's.
    fn surface(&mut self, head: &Head, ctx: &Ctx) -> Result<Option<Item>, Fail> {
        let args = crate::surface::surface_args(head)?;
        if ctx.skip {
            return Ok(None);
        }
        let path = self
            .options
            .dir
            .clone()
            .unwrap_or_default()
            .join(&args.file);
        let budget = self.max_vertices().saturating_sub(self.vertices);
        let read = crate::surface::read(&path, args.invert, budget).map_err(|e| Fail {
            pos: head.pos,
            problem: e.context(format_args!("`surface(\"{}\")`", args.file)),
        })?;
        let warned = !read.warnings.is_empty();
        self.warnings
            .extend(read.warnings.into_iter().map(|w| (head.pos, w)));
        let tris = crate::surface::mesh(&read.heights, args.center);
        if tris.is_empty() {
            if !warned {
                let (l, c) = (read.heights.lines(), read.heights.columns());
                let msg = format!(
                    "`surface(\"{}\")` has {l} × {c} heights (rows × columns): it encloses \
                     nothing (it is empty)",
                    args.file
                );
                self.warnings.push((head.pos, msg));
            }
            return Ok(Some(Item::Solid(CsgNode::Empty)));
        }
        self.vertices += tris.len() * 3;
        let to = Placement {
            matrix: ctx.matrix,
            colour: ctx.colour,
            pos: head.pos,
            name: "surface",
        };
        self.push_mesh(tris, &to).map(|n| Some(Item::Solid(n)))
    }

    fn leaf(&mut self, head: &Head, ctx: &Ctx) -> Result<Option<Item>, Fail> {
        if head.kind == NodeKind::Import {
            let dir = self.options.dir.as_deref();
            if let Some((msg, flat)) = crate::import::unreadable(head, dir) {
                return Ok(self.removed(Some(&msg), head.pos, ctx.skip, flat));
            }
        }
        if crate::import::is_svg(head) {
            return self.svg(head, ctx);
        }
        if crate::import::is_dxf(head) {
            return self.dxf(head, ctx, None);
        }
        if head.kind == NodeKind::Surface {
            return self.surface(head, ctx);
        }
        if head.kind == NodeKind::Import {
            return self.import_leaf(head, ctx);
        }
        let budget = self.max_vertices().saturating_sub(self.vertices);
        if head.kind.is_flat() {
            return self.flat_leaf(head, ctx, budget);
        }
        let shape = match head.kind {
            NodeKind::Cube => cube(&head.params)?,
            NodeKind::Sphere => sphere(&head.params, budget)?,
            NodeKind::Cylinder => cylinder(&head.params, budget)?,
            _ => match polyhedron(&head.params, budget, &mut self.warnings)? {
                None => return Ok(self.removed(None, head.pos, ctx.skip, false)),
                Some(Polyhedron::Convex(shape)) => Some(shape),
                Some(Polyhedron::Mesh(tris, welded)) => {
                    return self.mesh_polyhedron(&tris, &welded, head, ctx, budget);
                }
            },
        };
        let Some(shape) = shape else {
            self.empty_primitive(head, ctx);
            return Ok(Some(Item::Solid(CsgNode::Empty)));
        };
        check_budget(shape.vertices.len(), budget, head.pos)?;
        if ctx.skip {
            return Ok(None);
        }
        if let Some(msg) = removal_3d(ctx.matrix.as_ref()) {
            return Ok(self.removed(Some(msg), head.pos, false, false));
        }
        let solid = place(shape, ctx, head.pos)?;
        self.vertices += solid.vertices.len();
        self.solids.push(solid);
        Ok(Some(Item::Solid(CsgNode::Solid(self.solids.len() - 1))))
    }

    /// A 3D `import`: the file's solid, kept for the scene (removed under a matrix that
    /// flattens it).
    fn import_leaf(&mut self, head: &Head, ctx: &Ctx) -> Result<Option<Item>, Fail> {
        let import = import(head, ctx)?;
        if ctx.skip {
            return Ok(None);
        }
        if let Some(msg) = removal_3d(ctx.matrix.as_ref()) {
            return Ok(self.removed(Some(msg), head.pos, false, false));
        }
        self.imports.push(import);
        Ok(Some(Item::Solid(CsgNode::Solid(
            IMPORTED + self.imports.len() - 1,
        ))))
    }

    /// A 2D primitive (`square`, `circle`, `polygon`, `text`): its outline within the
    /// vertex `budget`, placed in the plane.
    fn flat_leaf(&mut self, head: &Head, ctx: &Ctx, budget: usize) -> Result<Option<Item>, Fail> {
        let mut notes = vec![];
        // Taken out while the shape is drawn: the font lookup borrows the reader.
        let mut drawn = std::mem::take(&mut self.texts);
        let shape = flat_shape(
            &head.params,
            || self.fonts(),
            budget,
            &mut notes,
            &mut drawn,
        );
        self.texts = drawn;
        let shape = shape?;
        if !ctx.skip {
            self.warnings
                .extend(notes.into_iter().map(|n| (head.pos, n)));
        }
        let Some(poly) = shape else {
            self.empty_primitive(head, ctx);
            return Ok(None);
        };
        let n = poly.points().count();
        check_budget(n, budget, head.pos)?;
        if ctx.skip {
            return Ok(None);
        }
        if let Some(msg) = removal_2d(ctx.matrix.as_ref()) {
            return Ok(self.removed(Some(msg), head.pos, false, true));
        }
        self.vertices += n;
        if head.params.node == NodeKind::Text {
            let charged = crate::text::charged_vertices(n) as u64;
            let bytes = charged.saturating_mul(crate::BYTES_PER_SCENE_VERTEX);
            self.drawing_bytes = self.drawing_bytes.saturating_add(bytes);
        }
        let poly = poly.transformed(plane_part(ctx.matrix.as_ref()));
        Ok(Some(Item::Flat(Region::Poly(poly), head.pos)))
    }

    /// A `polyhedron` that is not convex: its triangles within the vertex `budget`, placed
    /// as a mesh (with a warning when it is not closed).
    fn mesh_polyhedron(
        &mut self,
        tris: &[[[f64; 3]; 3]],
        welded: &csgpix_scene::trimesh::TriMesh,
        head: &Head,
        ctx: &Ctx,
        budget: usize,
    ) -> Result<Option<Item>, Fail> {
        check_budget(tris.len() * 3, budget, head.pos)?;
        if ctx.skip {
            return Ok(None);
        }
        let to = Placement {
            matrix: ctx.matrix,
            colour: ctx.colour,
            pos: head.pos,
            name: "polyhedron",
        };
        self.vertices += tris.len() * 3;
        self.warn_open_polyhedron(welded, head.pos);
        let tris = tris.iter().map(|t| t.map(DVec3::from)).collect();
        self.push_mesh(tris, &to).map(|n| Some(Item::Solid(n)))
    }

    /// A finished `linear_extrude` or `rotate_extrude`: the CSG tree of its 2D children's
    /// tree, each shape extruded (module [`crate::extrude`]).
    fn extrude(&mut self, frame: Frame) -> Result<Item, Fail> {
        let pos = frame.pos;
        if frame.flats.is_empty() {
            return Ok(Item::Solid(CsgNode::Empty));
        }
        if let Some(msg) = removal_3d(frame.placement.as_ref()) {
            self.warnings.push((pos, msg.to_string()));
            return Ok(Item::Solid(CsgNode::Empty));
        }
        let mut region = region_of(Op::Union, frame.flats);
        self.flat_bytes = self.flat_bytes.max(region_bytes(&region));
        // Twisted or unevenly scaled walls are triangulated between slices, which does not
        // commute with booleans: those take the booleans in the plane first, as OpenSCAD.
        let triangulated = matches!(frame.spec, Spec::Linear(a) if !a.linear.keeps_convex());
        // A shape reaching across the axis may leave only one side after the 2D booleans
        // (OpenSCAD revolves their result): those are taken in the plane first too.
        // (The points are visited where they are, and only for a revolution: a plate of
        // thousands of circles has millions, which two copies had held only to be looked at.)
        let across = matches!(frame.spec, Spec::Rotate { .. }) && {
            let (mut left, mut right) = (false, false);
            for_each_point(&region, &mut |p| {
                left |= p.x < 0.0;
                right |= p.x > 0.0;
            });
            left && right
        };
        if (triangulated || across) && !matches!(region, Region::Poly(_)) {
            region = Region::Poly(flatten(&region));
        }
        let how = match frame.spec {
            Spec::Linear(a) => Extrusion::Linear(linear_slices(a, &region)),
            Spec::Rotate { angle, res } => {
                let mut r = 0.0f64;
                for_each_point(&region, &mut |p| r = r.max(p.x.abs()));
                let res = Resolution {
                    fn_: res.0,
                    fa: res.1,
                    fs: res.2,
                };
                let f = (res.fragments_from_r(r) * angle.abs() / 360.0).max(1.0);
                if f > MAX_FRAGMENTS as f64 {
                    return fail(pos, too_many_fragments(f, false));
                }
                Extrusion::Rotate {
                    angle,
                    fragments: f as usize,
                }
            }
            _ => return fail(pos, Error::Internal("an extrusion without its parameters")),
        };
        let to = Placement {
            matrix: frame.placement,
            colour: frame.ctx.colour,
            pos,
            name: frame.kind.name(),
        };
        let region = match self.footprint(region, &how, &to)? {
            Ok(node) => return Ok(Item::Solid(node)),
            Err(region) => region,
        };
        let mut prisms = convex_prisms(&region, &how, &to).into_iter();
        let node = self.extrude_region(&region, &how, &to, &mut prisms)?;
        Ok(Item::Solid(node))
    }

    /// A straight extrusion of a large 2D tree as one footprint primitive
    /// ([`csgpix_scene::footprint`]), when [`ReadOptions::footprints`] asks for it: no twist,
    /// no scale, more outline points than the option's count, a placement that keeps the Z
    /// axis, and no operation above it that needs its geometry while the scene is read
    /// (`hull`, `minkowski`, `projection`, `resize` take prisms and meshes). The region
    /// back otherwise.
    fn footprint(
        &mut self,
        region: Region,
        how: &Extrusion,
        to: &Placement,
    ) -> Result<Result<CsgNode, Region>, Fail> {
        let Extrusion::Linear(l) = how else {
            return Ok(Err(region));
        };
        let straight = l.twist == 0.0 && l.scale == [1.0, 1.0] && l.height > 0.0;
        let matrix = to.matrix.unwrap_or(IDENTITY);
        let Some(least) = self.options.footprints else {
            return Ok(Err(region));
        };
        if !straight || !keeps_z(&matrix) || self.open.iter().any(|f| f.kind.needs_geometry()) {
            return Ok(Err(region));
        }
        let mut n = 0usize;
        for_each_point(&region, &mut |_| n += 1);
        if n <= least && !(self.options.concave_footprints && has_concave_shape(&region)) {
            return Ok(Err(region));
        }
        // Its points were counted against the budget as the shapes were read; a prism's
        // two rings are not made.
        let (z0, z1) = l.z();
        let mut f = Footprint::new([z0, z1], matrix);
        postfix(region, &mut f);
        // Every point lies within the placed box's corners (none for an empty tree).
        let (lo, hi) = f.bounds();
        let corners = match lo.x <= hi.x {
            true => vec![lo.to_array(), hi.to_array()],
            false => vec![],
        };
        check_placed(to, corners.into_iter())?;
        Ok(Ok(self.push_made(to, (None, Some(std::sync::Arc::new(f))))))
    }

    /// One 2D tree extruded: its operations kept, its shapes extruded, each taking the next
    /// of [`convex_prisms`]' results.
    fn extrude_region(
        &mut self,
        r: &Region,
        how: &Extrusion,
        to: &Placement,
        prisms: &mut impl Iterator<Item = Option<Result<ConvexSolid, Fail>>>,
    ) -> Result<CsgNode, Fail> {
        let (op, parts) = match r {
            Region::Poly(p) => return self.extrude_shape(p, how, to, prisms.next().flatten()),
            Region::Union(c) => (Op::Union, c),
            Region::Intersection(c) => (Op::Intersection, c),
            Region::Difference(c) => (Op::Difference, c),
        };
        let nodes = parts
            .iter()
            .map(|c| self.extrude_region(c, how, to, prisms))
            .collect::<Result<Vec<_>, _>>()?;
        Ok(combine(op, nodes))
    }

    /// One shape extruded: its convex prism when it stays convex (`prism`, made by
    /// [`convex_prisms`]), else a closed mesh primitive.
    fn extrude_shape(
        &mut self,
        p: &Poly2,
        how: &Extrusion,
        to: &Placement,
        prism: Option<Result<ConvexSolid, Fail>>,
    ) -> Result<CsgNode, Fail> {
        let budget = self.max_vertices().saturating_sub(self.vertices);
        let n = p.points().count();
        if let Some(solid) = prism {
            let solid = solid?;
            self.vertices += solid.vertices.len();
            self.solids.push(solid);
            return Ok(CsgNode::Solid(self.solids.len() - 1));
        }
        let rings = match how {
            Extrusion::Linear(l) => l.slices + 1,
            Extrusion::Rotate { fragments, .. } => fragments + 1,
        };
        check_budget(n.saturating_mul(rings), budget, to.pos)?;
        let tris = match how {
            Extrusion::Linear(l) => linear_mesh(p, l, &sin_cos_degrees),
            Extrusion::Rotate { angle, fragments } => {
                match rotate_mesh(p, *angle, *fragments, &sin_cos_degrees) {
                    Ok(tris) => tris,
                    // OpenSCAD 2021.01 reports this as an error and draws nothing for the
                    // node, but goes on with the rest of the design: so does csgpix.
                    Err(e) => {
                        self.warnings
                            .push((to.pos, format!("{} (nothing drawn)", e.problem())));
                        return Ok(CsgNode::Empty);
                    }
                }
            }
        };
        if tris.is_empty() {
            return Ok(CsgNode::Empty);
        }
        self.vertices += n * rings;
        self.push_mesh(tris, to)
    }

    /// A closed mesh made by the scene (in the coordinates below `to.matrix`) as an import
    /// leaf: placed, checked against the coordinate limit, named by its node and position.
    /// A polyhedron whose faces, corners welded, do not close a surface: OpenSCAD 2021.01's
    /// render drops it with an error (`createNefPolyhedronFromPolySet`, src/cgalutils.cc: "The
    /// given mesh is not closed!"); csgpix voxelizes it by its winding number
    /// (`csgpix_scene::winding`) and warns, naming the open edges.
    fn warn_open_polyhedron(&mut self, mesh: &csgpix_scene::trimesh::TriMesh, pos: Pos) {
        if let Ok(Some(what)) = mesh.open_edges_summary("polyhedron") {
            let msg = format!(
                "polyhedron is not closed: {what}; OpenSCAD's render drops it, csgpix \
                 voxelizes it by its generalized winding number (inside where at least 1/2, \
                 within its box)"
            );
            self.warnings.push((pos, msg));
        }
    }

    fn push_mesh(&mut self, tris: Vec<[DVec3; 3]>, to: &Placement) -> Result<CsgNode, Fail> {
        if let Some(msg) = removal_3d(to.matrix.as_ref()) {
            self.warnings.push((to.pos, msg.to_string()));
            return Ok(CsgNode::Empty);
        }
        let m = to.matrix.unwrap_or(IDENTITY);
        let tris: Vec<[Vec3; 3]> = tris
            .iter()
            .map(|t| t.map(|v| transform_point(&m, v.to_array())))
            .collect();
        check_placed(to, tris.iter().flatten().copied())?;
        Ok(self.push_made(to, (Some(std::sync::Arc::new(tris)), None)))
    }

    /// A primitive the scene made, a mesh or a footprint in scene coordinates (checked by
    /// [`check_placed`]), as an import leaf named by its node and position.
    fn push_made(&mut self, to: &Placement, (mesh, footprint): Made) -> CsgNode {
        self.imports.push(Import {
            file: format!("{} at {}", to.name, to.pos),
            threshold: None,
            matrix: None,
            colour: to.colour,
            line: to.pos.line,
            col: to.pos.col,
            footprint,
            mesh,
        });
        CsgNode::Solid(IMPORTED + self.imports.len() - 1)
    }

    /// The solids and imports, less those a `hull()` took in, and the tree's leaves renumbered
    /// to match (imports still counted from [`IMPORTED`]).
    fn drop_consumed(&mut self, root: &mut CsgNode) -> (Vec<ConvexSolid>, Vec<Import>) {
        let keep = |n: usize, gone: &[usize]| -> (Vec<bool>, Vec<usize>) {
            let mut k = vec![true; n];
            gone.iter().for_each(|&i| k[i] = false);
            let mut next = 0;
            let map = k
                .iter()
                .map(|&kept| {
                    next += usize::from(kept);
                    next - usize::from(kept)
                })
                .collect();
            (k, map)
        };
        let (ks, ms) = keep(self.solids.len(), &self.consumed_solids);
        let (ki, mi) = keep(self.imports.len(), &self.consumed_imports);
        root.for_each_leaf_mut(|n| {
            if let CsgNode::Solid(i) = n {
                *i = if *i >= IMPORTED {
                    IMPORTED + mi[*i - IMPORTED]
                } else {
                    ms[*i]
                };
            }
        });
        let solids = std::mem::take(&mut self.solids);
        let imports = std::mem::take(&mut self.imports);
        (
            solids
                .into_iter()
                .zip(ks)
                .filter(|(_, k)| *k)
                .map(|(s, _)| s)
                .collect(),
            imports
                .into_iter()
                .zip(ki)
                .filter(|(_, k)| *k)
                .map(|(s, _)| s)
                .collect(),
        )
    }

    /// A finished `hull()` of solids: one convex solid over every vertex of the solids and
    /// generated meshes below it (through unions), of each intersection of convex solids
    /// among them ([`crate::clip::convex_intersection`]) and of the computed mesh of each
    /// other difference or intersection ([`crate::geom::mesh_of`]); all of them leave the
    /// scene.
    fn hull3(&mut self, frame: Frame) -> Result<Item, Fail> {
        let pos = frame.pos;
        let at = |problem: Error| Fail { pos, problem };
        let mut pts: Vec<DVec3> = vec![];
        let mut stack: Vec<&CsgNode> = frame.children.iter().collect();
        while let Some(n) = stack.pop() {
            match n {
                CsgNode::Empty => {}
                CsgNode::Union(c) => stack.extend(c.iter()),
                CsgNode::Solid(leaf) => {
                    let mesh = leaf_mesh(*leaf, &self.solids, &self.imports)
                        .map_err(|e| at(e.context("hull()")))?;
                    pts.extend(mesh.iter().flatten());
                }
                _ => match (self.meshes.solid_of(n, &self.solids, &self.imports))
                    .map_err(|e| at(e.context("hull()")))?
                {
                    Solid::Convex(p) => pts.extend(p.v),
                    Solid::Mesh(m) => pts.extend(m.iter().flatten()),
                },
            }
        }
        for c in &frame.children {
            self.consume(c);
        }
        if pts.is_empty() {
            return Ok(Item::Solid(CsgNode::Empty));
        }
        let (vertices, faces) = hull3(&pts).map_err(at)?;
        let solid = ConvexSolid {
            vertices: vertices.iter().map(|v| v.to_array()).collect(),
            faces: faces.into(),
            colour: frame.ctx.colour,
            line: pos.line,
        };
        self.vertices += solid.vertices.len();
        self.solids.push(solid);
        Ok(Item::Solid(CsgNode::Solid(self.solids.len() - 1)))
    }

    /// Every leaf of `n` leaves the scene at the end ([`Self::drop_consumed`]).
    fn consume(&mut self, n: &CsgNode) {
        for i in crate::project::leaves(n) {
            match i.checked_sub(IMPORTED) {
                Some(j) => self.consumed_imports.push(j),
                None => self.consumed_solids.push(i),
            }
        }
    }

    /// A finished `minkowski()` of solids: the left fold of its children's sums
    /// ([`crate::geom`]) in their own coordinates, each a union of convex solids and closed
    /// mesh primitives, placed by the transform above; the children's leaves leave the scene.
    /// One child is itself. The same statement met again takes the sum already made
    /// ([`Self::sums`]), or the same error when the budget left is smaller than it needed.
    fn minkowski3(&mut self, mut frame: Frame) -> Result<Item, Fail> {
        let pos = frame.pos;
        let at = |e: Error| Fail {
            pos,
            problem: e.context("minkowski()"),
        };
        // OpenSCAD leaves empty children out of the sum.
        frame.children.retain(|c| !matches!(c, CsgNode::Empty));
        if frame.children.len() < 2 {
            let node = frame.children.pop().unwrap_or(CsgNode::Empty);
            self.place(&node, frame.placement.as_ref(), pos)?;
            return Ok(Item::Solid(node));
        }
        let budget = self.max_vertices().saturating_sub(self.vertices);
        let key = spaced_once(&self.text[frame.start..self.parser.last_end]);
        let sum = match self.sums.remove(&key) {
            Some(sum) if sum.need > budget => return Err(at(crate::geom::over_budget())),
            Some(sum) => sum,
            None => {
                let sum = self.sum_children(&frame.children, budget).map_err(at)?;
                self.kept_bytes = self.kept_bytes.saturating_add(sum.bytes());
                sum
            }
        };
        for c in &frame.children {
            self.consume(c);
        }
        let node = self.sum_leaves(&sum.parts, frame.ctx.colour, pos);
        self.sums.insert(key, sum);
        self.place(&node, frame.placement.as_ref(), pos)?;
        check_budget(self.vertices, self.max_vertices(), pos)?;
        Ok(Item::Solid(node))
    }

    /// A finished `offset()`: its outline in its own coordinates, the one made before when the
    /// same statement was met (a module called again), placed by the transform above it.
    fn offset(&mut self, frame: Frame) -> Result<Option<Item>, Fail> {
        let key = spaced_once(&self.text[frame.start..self.parser.last_end]);
        let m = plane_part(frame.placement.as_ref());
        let (region, at) = match self.outlines.get(&key) {
            Some(r) => (r.clone(), frame.first_flat.unwrap_or(frame.pos)),
            None => match offset_flat(frame)? {
                Some((r, at)) => {
                    self.kept_bytes = self.kept_bytes.saturating_add(region_bytes(&r));
                    self.outlines.insert(key, r.clone());
                    (r, at)
                }
                None => return Ok(None),
            },
        };
        Ok(Some(Item::Flat(
            map_region(region, &|p| p.transformed(m)),
            at,
        )))
    }

    /// The left fold of `children`'s sums, and the most vertices a step was counted to bring.
    fn sum_children(&mut self, children: &[CsgNode], budget: usize) -> Result<Sum, Error> {
        let mut acc: Option<Vec<Piece>> = None;
        let mut need = 0;
        for c in children {
            let p = pieces(c, &self.solids, &self.imports, &mut self.meshes)?;
            if p.is_empty() {
                continue;
            }
            acc = Some(match acc {
                None => p,
                Some(a) => {
                    let (sum, step) = minkowski3(&a, &p, budget)?;
                    need = need.max(step);
                    sum
                }
            });
        }
        Ok(Sum::of(acc.unwrap_or_default(), need))
    }

    /// A sum's parts as the scene's leaves, in `colour`, made by the statement at `pos`:
    /// convex solids and closed meshes, in a union.
    fn sum_leaves(&mut self, parts: &[SumPart], colour: Option<[f64; 4]>, pos: Pos) -> CsgNode {
        let mut leaves = vec![];
        for p in parts {
            match p {
                SumPart::Convex(s) => {
                    let line = pos.line;
                    let solid = ConvexSolid {
                        colour,
                        line,
                        ..s.clone()
                    };
                    self.vertices += solid.vertices.len();
                    self.solids.push(solid);
                    leaves.push(CsgNode::Solid(self.solids.len() - 1));
                }
                SumPart::Mesh(m) => {
                    self.vertices += m.len() * 3;
                    self.imports.push(Import {
                        file: format!("minkowski at {pos}"),
                        threshold: None,
                        matrix: None,
                        colour,
                        line: pos.line,
                        col: pos.col,
                        footprint: None,
                        mesh: Some(m.clone()),
                    });
                    leaves.push(CsgNode::Solid(IMPORTED + self.imports.len() - 1));
                }
            }
        }
        combine(Op::Union, leaves)
    }

    /// The leaves under `node`, made in their own coordinates, moved by `placement` (the
    /// transform above the node that made them).
    fn place(&mut self, node: &CsgNode, placement: Option<&Mat4>, pos: Pos) -> Result<(), Fail> {
        let Some(m) = placement else {
            return Ok(());
        };
        let past_limit = coordinate_too_large(None);
        move_leaves(
            node,
            &mut self.solids,
            &mut self.imports,
            m,
            (pos, past_limit),
        )
    }

    /// A finished `minkowski()` of 2D shapes: the left fold of the sums, a 2D union of
    /// convex polygons and shapes.
    fn minkowski2(&mut self, mut frame: Frame) -> Result<Option<Item>, Fail> {
        let pos = frame.pos;
        let flat_at = frame.first_flat.unwrap_or(pos);
        if frame.flats.len() < 2 {
            let placed = |r| placed_flat(r, frame.placement.as_ref());
            return Ok(frame.flats.pop().map(|r| Item::Flat(placed(r), flat_at)));
        }
        let budget = self.max_vertices().saturating_sub(self.vertices);
        let mut acc: Option<Vec<Piece2>> = None;
        for r in &frame.flats {
            let p = pieces2(r);
            if p.is_empty() {
                continue;
            }
            acc = Some(match acc {
                None => p,
                Some(a) => minkowski2(&a, &p, budget).map_err(|e| Fail {
                    pos,
                    problem: e.context("minkowski()"),
                })?,
            });
        }
        let parts: Vec<Region> = acc
            .unwrap_or_default()
            .into_iter()
            .map(|p| match p {
                Piece2::Convex(h) => Region::Poly(Poly2 { paths: vec![h] }),
                Piece2::Shape(s) => Region::Poly(s),
            })
            .collect();
        let n: usize = parts
            .iter()
            .map(|r| match r {
                Region::Poly(p) => p.points().count(),
                _ => 0,
            })
            .sum();
        check_budget(n, budget, pos)?;
        self.vertices += n;
        if parts.is_empty() {
            return Ok(None);
        }
        let region = region_of(Op::Union, parts);
        Ok(Some(Item::Flat(
            placed_flat(region, frame.placement.as_ref()),
            flat_at,
        )))
    }
}

/// `text` with each run of white space outside string literals as one space: two statements
/// differ in it only where their tokens differ.
pub(crate) fn spaced_once(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let (mut in_string, mut escaped, mut space) = (false, false, false);
    for c in text.chars() {
        if !in_string && c.is_ascii_whitespace() {
            space = true;
            continue;
        }
        if space && !out.is_empty() {
            out.push(' ');
        }
        space = false;
        out.push(c);
        match (in_string, escaped, c) {
            (true, true, _) => escaped = false,
            (true, false, '\\') => escaped = true,
            (_, _, '"') => in_string = !in_string,
            _ => {}
        }
    }
    out
}

/// A 2D result made in its own coordinates, moved in the plane by `placement` (the transform
/// above the node that made it).
fn placed_flat(region: Region, placement: Option<&Mat4>) -> Region {
    match placement {
        Some(m) => {
            let m = plane_part(Some(m));
            map_region(region, &|p| p.transformed(m))
        }
        None => region,
    }
}

/// Where an extrusion's solids go: the transform above it, its colour, for messages its
/// position and name.
struct Placement {
    matrix: Option<Mat4>,
    colour: Option<[f64; 4]>,
    pos: Pos,
    name: &'static str,
}

/// Tree `r`'s shapes and operations onto `f` in postfix order, with an explicit stack; each
/// shape is freed once copied, so the tree and the footprint are not both held whole.
fn postfix(r: Region, f: &mut Footprint) {
    enum Visit {
        Enter(Region),
        Leave(FootOp, usize),
    }
    let mut stack = vec![Visit::Enter(r)];
    while let Some(v) = stack.pop() {
        let (op, c) = match v {
            Visit::Leave(op, n) => {
                f.push_op(op, n);
                continue;
            }
            Visit::Enter(Region::Poly(p)) => {
                f.push_shape(p.paths.iter().map(|p| p.as_slice()));
                continue;
            }
            Visit::Enter(Region::Union(c)) => (FootOp::Union, c),
            Visit::Enter(Region::Intersection(c)) => (FootOp::Intersection, c),
            Visit::Enter(Region::Difference(c)) => (FootOp::Difference, c),
        };
        stack.push(Visit::Leave(op, c.len()));
        stack.extend(c.into_iter().rev().map(Visit::Enter));
    }
}

/// The checks every placed primitive passes, on `points` (all it reaches): coordinates
/// within the limit, no degenerate extent.
fn check_placed(
    to: &Placement,
    points: impl Iterator<Item = [f64; 3]> + Clone,
) -> Result<(), Fail> {
    if points.clone().flatten().any(too_large) {
        return fail(to.pos, coordinate_too_large(None));
    }
    match degenerate_extent(points) {
        Some(problem) => fail(to.pos, problem),
        None => Ok(()),
    }
}

/// What the scene made of a node that is not a convex solid: a closed mesh or a footprint.
type Made = (
    Option<std::sync::Arc<Vec<[Vec3; 3]>>>,
    Option<std::sync::Arc<Footprint>>,
);

/// An extrusion, its slice or fragment count settled.
enum Extrusion {
    Linear(Linear),
    Rotate { angle: f64, fragments: usize },
}

fn unsupported(name: &str) -> CsgError {
    CsgError::UnsupportedNode {
        name: name.to_string(),
        known: NODES.iter().map(|(n, _)| *n).collect(),
    }
}

/// `expected` what closes `frame`, `found` what came instead.
fn unclosed(frame: &Frame, found: &str) -> Error {
    let name = frame.kind.name();
    let expected = match frame.closer {
        Closer::Brace(at) => format!("'}}' to close `{name}` opened at {at}"),
        Closer::Single => format!("a child statement or ';' after `{name}(…)`"),
    };
    Error::Expected {
        expected,
        found: found.to_string(),
    }
}

/// The context of the children of `head` (or of `head` itself, for a leaf).
fn child_ctx(parent: &Ctx, head: &Head, warnings: &mut Vec<(Pos, String)>) -> Result<Ctx, Fail> {
    let mut ctx = parent.clone();
    ctx.skip |= head.skip;
    match head.kind {
        NodeKind::Multmatrix => {
            if let Some(m) = matrix(&head.params)? {
                ctx.matrix = Some(match &parent.matrix {
                    Some(outer) => mat_mul(outer, &m),
                    None => m,
                });
            }
        }
        NodeKind::Color if !ctx.skip => ctx.colour = Some(colour(&head.params, warnings)?),
        NodeKind::Color => ctx.colour = Some(colour(&head.params, &mut vec![])?),
        _ => {}
    }
    Ok(ctx)
}

// ---------------------------------------------------------------------------------------------
// CSG tree

/// The convex prism of every shape of 2D tree `r` that stays convex under extrusion `how`
/// (None for the others), in the order [`Reader::extrude_region`] meets the shapes, made in
/// parallel: a tree of thousands of circles of many fragments is as many prisms of as many
/// faces. A shape's error is kept for the moment the reader reaches it, so errors come in the
/// order they did one shape at a time.
fn convex_prisms(
    r: &Region,
    how: &Extrusion,
    to: &Placement,
) -> Vec<Option<Result<ConvexSolid, Fail>>> {
    use rayon::prelude::*;
    let Extrusion::Linear(l) = how else {
        return vec![];
    };
    let mut shapes = vec![];
    region_shapes(r, &mut shapes);
    let ctx = Ctx {
        matrix: to.matrix,
        colour: to.colour,
        skip: false,
    };
    shapes
        .par_iter()
        .map(|p| {
            let outline = p.convex_outline().filter(|_| l.keeps_convex())?;
            let (vertices, faces) = convex_prism(&outline, l);
            Some(place(Shape { vertices, faces }, &ctx, to.pos))
        })
        .collect()
}

/// Whether a shape of 2D tree `r` is not convex: extruded, it would be a mesh primitive.
fn has_concave_shape(r: &Region) -> bool {
    let mut shapes = vec![];
    region_shapes(r, &mut shapes);
    shapes.iter().any(|p| p.convex_outline().is_none())
}

/// The shapes of 2D tree `r`, depth first, in order.
fn region_shapes<'r>(r: &'r Region, out: &mut Vec<&'r Poly2>) {
    match r {
        Region::Poly(p) => out.push(p),
        Region::Union(c) | Region::Intersection(c) | Region::Difference(c) => {
            c.iter().for_each(|c| region_shapes(c, out))
        }
    }
}
