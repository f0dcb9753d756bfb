"""Write the coarse mesh of a layered box cut by faults as a Gmsh MSH 2.2
file, the way the layered-box generator builds it (rows of vertices, the
columns between the sides and the faults divided evenly in every row), with
the sides as physical curves left, right, base, top, each fault as a
physical curve of its name and the cells as the physical surface "rock".
Used by the tests to check that a fault read from a Gmsh physical curve
gives what the built-in generator gives."""


def graded(fine, n_fine, growth, far):
    """Distances 0, fine, ..., n_fine fine, then growing by growth to far."""
    d = [fine * k for k in range(n_fine + 1)]
    h = fine
    while d[-1] < far:
        h *= growth
        d.append(d[-1] + h)
    return d


def write_msh(path, rows, groups):
    """rows: the vertex rows from the base up, each a list of x for its y
    ((y, [x0, x1, ...]), all rows the same length); groups: physical curves
    as {name: [(i, j, i2, j2), ...]} edges between vertex (i, j) and (i2,
    j2) (column, row). Cells: the quads between neighbouring rows and
    columns, physical surface "rock"."""
    nx = len(rows[0][1])
    node = lambda i, j: j * nx + i + 1  # noqa: E731
    names = {name: 1 + k for k, name in enumerate(groups)}
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n%d\n" % (len(names) + 1))
        for name, tag in names.items():
            f.write('1 %d "%s"\n' % (tag, name))
        f.write('2 100 "rock"\n$EndPhysicalNames\n$Nodes\n%d\n' % (nx * len(rows)))
        for j, (y, xs) in enumerate(rows):
            for i, x in enumerate(xs):
                f.write("%d %.17g %.17g 0\n" % (node(i, j), x, y))
        edges = [(names[name], e) for name, es in groups.items() for e in es]
        quads = [(node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1))
                 for j in range(len(rows) - 1) for i in range(nx - 1)]
        f.write("$EndNodes\n$Elements\n%d\n" % (len(edges) + len(quads)))
        number = 1
        for tag, (i, j, i2, j2) in edges:
            f.write("%d 1 2 %d %d %d %d\n" % (number, tag, tag, node(i, j), node(i2, j2)))
            number += 1
        for q in quads:
            f.write("%d 3 2 100 100 %d %d %d %d\n" % ((number,) + q))
            number += 1
        f.write("$EndElements\n")


def layered_box_msh(path, width, ys, faults, first_columns):
    """ys: the rows' heights from the base up; faults: [(name, x(y))] left
    to right; first_columns: the first column of each block and the total,
    e.g. [0, 2, 4, 6] for two faults and 6 columns."""
    n_across = first_columns[-1]
    nx = n_across + 1

    def x_of(i, y):
        k = 0
        while k + 2 < len(first_columns) and i > first_columns[k + 1]:
            k += 1
        left = 0.0 if k == 0 else faults[k - 1][1](y)
        right = width if k == len(faults) else faults[k][1](y)
        return left + (right - left) * (i - first_columns[k]) / (first_columns[k + 1] - first_columns[k])

    nodes = []
    for y in ys:
        for i in range(nx):
            nodes.append((x_of(i, y), y))
    node = lambda i, j: j * nx + i + 1  # noqa: E731
    names = {"left": 1, "right": 2, "base": 3, "top": 4}
    for k, (name, _) in enumerate(faults):
        names[name] = 5 + k
    lines = []
    for j in range(len(ys) - 1):
        lines.append((names["left"], node(0, j), node(0, j + 1)))
        lines.append((names["right"], node(n_across, j), node(n_across, j + 1)))
        for k, (name, _) in enumerate(faults):
            c = first_columns[k + 1]
            lines.append((names[name], node(c, j), node(c, j + 1)))
    for i in range(n_across):
        lines.append((names["base"], node(i, 0), node(i + 1, 0)))
        lines.append((names["top"], node(i, len(ys) - 1), node(i + 1, len(ys) - 1)))
    quads = [(node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1))
             for j in range(len(ys) - 1) for i in range(n_across)]
    with open(path, "w") as f:
        f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n%d\n" % (len(names) + 1))
        for name, tag in names.items():
            f.write('1 %d "%s"\n' % (tag, name))
        f.write('2 100 "rock"\n$EndPhysicalNames\n$Nodes\n%d\n' % len(nodes))
        for i, (x, y) in enumerate(nodes):
            f.write("%d %.17g %.17g 0\n" % (i + 1, x, y))
        f.write("$EndNodes\n$Elements\n%d\n" % (len(lines) + len(quads)))
        number = 1
        for tag, a, b in lines:
            f.write("%d 1 2 %d %d %d %d\n" % (number, tag, tag, a, b))
            number += 1
        for q in quads:
            f.write("%d 3 2 100 100 %d %d %d %d\n" % ((number,) + q))
            number += 1
        f.write("$EndElements\n")
