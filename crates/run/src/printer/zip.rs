//! A zip archive written as it goes (PKWARE APPNOTE 6.3, stored entries): every member is
//! whole in memory when it is added (a layer PNG, an ini file), so its CRC and size are in
//! its local header and no data descriptor is needed, and nothing is seeked back to. The
//! layer PNGs are deflated already; storing them costs nothing in size.

use std::io::Write;

/// The most members a zip without ZIP64 records holds.
pub const MAX_MEMBERS: usize = 65_535;

/// A member's central-directory fields.
struct Member {
    name: String,
    crc: u32,
    size: u32,
    offset: u32,
}

/// A zip being written into `w`.
pub struct ZipOut<'w> {
    w: &'w mut dyn Write,
    at: u64,
    members: Vec<Member>,
}

fn too_large(what: &str) -> std::io::Error {
    std::io::Error::other(format!(
        "the archive's {what} passes 4 GiB (a zip without ZIP64)"
    ))
}

impl<'w> ZipOut<'w> {
    pub fn new(w: &'w mut dyn Write) -> ZipOut<'w> {
        ZipOut {
            w,
            at: 0,
            members: vec![],
        }
    }

    /// Add member `name` holding `data`.
    pub fn add(&mut self, name: &str, data: &[u8]) -> std::io::Result<()> {
        if self.members.len() >= MAX_MEMBERS {
            return Err(std::io::Error::other(
                "more than 65,535 files in one archive",
            ));
        }
        let size = u32::try_from(data.len()).map_err(|_| too_large("member"))?;
        let offset = u32::try_from(self.at).map_err(|_| too_large("size"))?;
        let crc = crc32fast::hash(data);
        let mut h = Vec::with_capacity(30 + name.len());
        h.extend_from_slice(&0x0403_4b50u32.to_le_bytes());
        h.extend_from_slice(&[20, 0, 0, 0, 0, 0]); // version 2.0, no flags, stored
        h.extend_from_slice(&DOS_TIME);
        h.extend_from_slice(&crc.to_le_bytes());
        h.extend_from_slice(&size.to_le_bytes());
        h.extend_from_slice(&size.to_le_bytes());
        h.extend_from_slice(&(name.len() as u16).to_le_bytes());
        h.extend_from_slice(&[0, 0]);
        h.extend_from_slice(name.as_bytes());
        self.w.write_all(&h)?;
        self.w.write_all(data)?;
        self.at += (h.len() + data.len()) as u64;
        let name = name.to_string();
        self.members.push(Member {
            name,
            crc,
            size,
            offset,
        });
        Ok(())
    }

    /// The central directory and its end record.
    pub fn finish(self) -> std::io::Result<()> {
        let start = u32::try_from(self.at).map_err(|_| too_large("size"))?;
        let mut d = vec![];
        for m in &self.members {
            d.extend_from_slice(&0x0201_4b50u32.to_le_bytes());
            d.extend_from_slice(&[20, 3, 20, 0, 0, 0, 0, 0]); // made by Unix 2.0
            d.extend_from_slice(&DOS_TIME);
            d.extend_from_slice(&m.crc.to_le_bytes());
            d.extend_from_slice(&m.size.to_le_bytes());
            d.extend_from_slice(&m.size.to_le_bytes());
            d.extend_from_slice(&(m.name.len() as u16).to_le_bytes());
            d.extend_from_slice(&[0; 8]); // extra, comment, disk, internal attributes
            d.extend_from_slice(&(0o100644u32 << 16).to_le_bytes());
            d.extend_from_slice(&m.offset.to_le_bytes());
            d.extend_from_slice(m.name.as_bytes());
        }
        let n = self.members.len() as u16;
        let size = u32::try_from(d.len()).map_err(|_| too_large("directory"))?;
        d.extend_from_slice(&0x0605_4b50u32.to_le_bytes());
        d.extend_from_slice(&[0, 0, 0, 0]);
        d.extend_from_slice(&n.to_le_bytes());
        d.extend_from_slice(&n.to_le_bytes());
        d.extend_from_slice(&size.to_le_bytes());
        d.extend_from_slice(&start.to_le_bytes());
        d.extend_from_slice(&[0, 0]);
        self.w.write_all(&d)
    }
}

/// Every member's time: 1980-01-01 00:00, so that an archive is the same bytes run after run.
const DOS_TIME: [u8; 4] = [0, 0, 0x21, 0];

#[cfg(test)]
mod tests {
    use super::*;

    /// A standard reader lists the members and reads their bytes back.
    #[test]
    fn a_reader_gets_every_member_back() {
        let mut bytes = vec![];
        let mut z = ZipOut::new(&mut bytes);
        z.add("config.ini", b"action = print\n").unwrap();
        z.add("a00000.png", &[0u8, 1, 2, 255]).unwrap();
        z.add("empty", &[]).unwrap();
        z.finish().unwrap();
        let mut a = zip::ZipArchive::new(std::io::Cursor::new(bytes)).unwrap();
        assert_eq!(a.len(), 3);
        let mut read = |name: &str| {
            let mut f = a.by_name(name).unwrap();
            let mut v = vec![];
            std::io::Read::read_to_end(&mut f, &mut v).unwrap();
            v
        };
        assert_eq!(read("config.ini"), b"action = print\n");
        assert_eq!(read("a00000.png"), [0u8, 1, 2, 255]);
        assert!(read("empty").is_empty());
    }
}
