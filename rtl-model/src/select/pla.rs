//! Berkeley Espresso PLA files, `.type fd` (interim writer/parser).

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Out {
    Zero,
    One,
    DontCare,
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Row {
    pub comments: Vec<String>,
    pub inputs: Vec<Option<bool>>,
    pub outputs: Vec<Out>,
}

#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Pla {
    pub header: Vec<String>,
    pub inputs: Vec<String>,
    pub outputs: Vec<String>,
    pub rows: Vec<Row>,
    pub trailer: Vec<String>,
}

#[derive(Debug, Clone, PartialEq, Eq)]
pub struct PlaError {
    pub line: usize,
    pub col: usize,
    pub msg: String,
}

impl std::fmt::Display for PlaError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "{}:{}: {}", self.line, self.col, self.msg)
    }
}

impl std::error::Error for PlaError {}

impl Pla {
    pub fn to_text(&self) -> String {
        let mut s: String = self.header.iter().map(|h| format!("# {h}\n")).collect();
        s += &format!(".i {}\n.o {}\n", self.inputs.len(), self.outputs.len());
        s += &format!(
            ".ilb {}\n.ob {}\n.type fd\n.p {}\n",
            self.inputs.join(" "),
            self.outputs.join(" "),
            self.rows.len()
        );
        for r in &self.rows {
            for c in &r.comments {
                s += &format!("# {c}\n");
            }
            let i: String = r
                .inputs
                .iter()
                .map(|b| match b {
                    Some(true) => '1',
                    Some(false) => '0',
                    None => '-',
                })
                .collect();
            let o: String = r
                .outputs
                .iter()
                .map(|b| match b {
                    Out::One => '1',
                    Out::Zero => '0',
                    Out::DontCare => '-',
                })
                .collect();
            s += &format!("{i} {o}\n");
        }
        for t in &self.trailer {
            s += &format!("# {t}\n");
        }
        s + ".e\n"
    }

    pub fn parse(text: &str) -> Result<Pla, PlaError> {
        let mut p = Pla {
            header: vec![],
            inputs: vec![],
            outputs: vec![],
            rows: vec![],
            trailer: vec![],
        };
        let (mut ni, mut no) = (None::<usize>, None::<usize>);
        let mut pending: Vec<String> = vec![];
        for (ln, line) in text.lines().enumerate() {
            let ln = ln + 1;
            let err = |col: usize, msg: String| PlaError { line: ln, col, msg };
            let t = line.trim();
            if t.is_empty() {
                continue;
            }
            if let Some(c) = t.strip_prefix('#') {
                pending.push(c.strip_prefix(' ').unwrap_or(c).to_string());
                continue;
            }
            if t.starts_with('.') {
                let mut f = t.split_whitespace();
                let d = f.next().unwrap();
                let rest: Vec<&str> = f.collect();
                match d {
                    ".i" => ni = rest.first().and_then(|v| v.parse().ok()),
                    ".o" => no = rest.first().and_then(|v| v.parse().ok()),
                    ".ilb" => p.inputs = rest.iter().map(|s| s.to_string()).collect(),
                    ".ob" => p.outputs = rest.iter().map(|s| s.to_string()).collect(),
                    ".type" if rest == ["fd"] => {}
                    ".p" | ".e" | ".end" => {}
                    _ => return Err(err(1, format!("unknown directive {d}"))),
                }
                if p.rows.is_empty() && p.header.is_empty() {
                    p.header = std::mem::take(&mut pending);
                }
                continue;
            }
            let (ni, no) = match (ni, no) {
                (Some(i), Some(o)) => (i, o),
                _ => return Err(err(1, "expected .i and .o before the first row".into())),
            };
            let chars: Vec<(usize, char)> = line
                .chars()
                .enumerate()
                .filter(|c| !c.1.is_whitespace())
                .collect();
            if chars.len() != ni + no {
                return Err(err(
                    1,
                    format!("expected {} input and {} output characters", ni, no),
                ));
            }
            let mut inputs = vec![];
            for &(c, ch) in &chars[..ni] {
                inputs.push(match ch {
                    '0' => Some(false),
                    '1' => Some(true),
                    '-' => None,
                    _ => return Err(err(c + 1, format!("expected 0, 1 or -, found {ch:?}"))),
                });
            }
            let mut outputs = vec![];
            for &(c, ch) in &chars[ni..] {
                outputs.push(match ch {
                    '0' | '~' => Out::Zero,
                    '1' => Out::One,
                    '-' | '2' => Out::DontCare,
                    _ => return Err(err(c + 1, format!("expected 0, 1 or -, found {ch:?}"))),
                });
            }
            p.rows.push(Row {
                comments: std::mem::take(&mut pending),
                inputs,
                outputs,
            });
        }
        p.trailer = pending;
        Ok(p)
    }

    pub fn minterms(&self) -> Vec<(u32, Vec<Out>)> {
        let mut v = vec![];
        for r in &self.rows {
            let free: Vec<usize> = (0..r.inputs.len())
                .filter(|&i| r.inputs[i].is_none())
                .collect();
            let base = r
                .inputs
                .iter()
                .enumerate()
                .fold(0u32, |m, (i, b)| m | ((*b == Some(true)) as u32) << i);
            for k in 0..1u32 << free.len() {
                let m = free
                    .iter()
                    .enumerate()
                    .fold(base, |m, (j, &i)| m | (k >> j & 1) << i);
                v.push((m, r.outputs.clone()));
            }
        }
        v
    }
}
