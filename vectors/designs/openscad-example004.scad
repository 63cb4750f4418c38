// Source: openscad/openscad examples/Old/example004.scad@41f58fe57c03457a3a8b4dc541ef5654ec3e8c78, licence CC0-1.0

module example004()
{
  difference() {
    cube(30, center = true);
    sphere(20);
  }
}

echo(version=version());

example004();

// Written by Clifford Wolf <clifford@clifford.at> and Marius
// Kintel <marius@kintel.net>
//
// To the extent possible under law, the author(s) have dedicated all
// copyright and related and neighboring rights to this software to the
// public domain worldwide. This software is distributed without any
// warranty.
//
// You should have received a copy of the CC0 Public Domain
// Dedication along with this software.
// If not, see <http://creativecommons.org/publicdomain/zero/1.0/>.
