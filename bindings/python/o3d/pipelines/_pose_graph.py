"""PoseGraph's list-like ``nodes`` / ``edges`` and the PoseGraphNode / PoseGraphEdge values, as Open3D's.

A node or edge is either free-standing (it holds its own values) or a view of one entry of a graph
(``pose_graph.nodes[i]``): reading a view's attribute reads the graph, assigning one writes it, so
``pose_graph.nodes[i].pose = T`` and ``pose_graph.edges[i].confidence`` work as in Open3D. Appending copies
the values into the graph. Matrices read back are read-only arrays (as Open3D's); assign a new matrix to
change one.
"""
from collections.abc import MutableSequence

import numpy as np

from .. import _o3d


def _matrix(value, n, what):
    a = np.array(value, dtype=np.float64)
    if a.shape != (n, n):
        raise _o3d.InvalidArgumentError(f"{what}: expected shape ({n}, {n}), got {a.shape}")
    a.setflags(write=False)
    return a


def _index(i, n):
    if not isinstance(i, (int, np.integer)) or isinstance(i, bool):
        raise TypeError(f"indices must be integers or slices, not {type(i).__name__}")
    i = int(i)
    if i < 0:
        i += n
    if not 0 <= i < n:
        raise IndexError("pose graph index out of range")
    return i


class PoseGraphNode:
    """A pose (4x4 transformation from the node's frame to the world frame)."""

    __slots__ = ("_graph", "_i", "_pose")

    def __init__(self, pose=None):
        if isinstance(pose, PoseGraphNode):  # copy constructor
            pose = pose.pose
        self._graph = None
        self._i = -1
        self._pose = _matrix(np.identity(4) if pose is None else pose, 4, "pose")

    @classmethod
    def _view(cls, graph, i):
        node = cls.__new__(cls)
        node._graph, node._i, node._pose = graph, i, None
        return node

    @property
    def pose(self):
        return _matrix(self._graph._get_node(self._i), 4, "pose") if self._graph is not None else self._pose

    @pose.setter
    def pose(self, value):
        if self._graph is not None:
            self._graph._set_node(self._i, _matrix(value, 4, "pose"))
        else:
            self._pose = _matrix(value, 4, "pose")

    def __copy__(self):
        return PoseGraphNode(self.pose)

    def __deepcopy__(self, memo):
        return PoseGraphNode(self.pose)

    def __reduce__(self):
        return PoseGraphNode, (np.array(self.pose),)

    def __repr__(self):
        return "PoseGraphNode, access pose to get its current pose."


_EDGE_FIELDS = ("source_node_id", "target_node_id", "transformation", "information", "uncertain", "confidence")


class PoseGraphEdge:
    """Edge (source_node_id, target_node_id, transformation, information, uncertain, confidence): transformation
    maps points of the source node's frame into the target node's; uncertain marks a loop closure the line
    process may prune; confidence is its line-process weight."""

    __slots__ = ("_graph", "_i", "_values")

    # Node ids default to -1 as Open3D's (the C edge's 0 would name a real node); the rest comes from
    # o3d_pose_graph_edge_init.
    _, _, _TRANSFORMATION, _INFORMATION, _UNCERTAIN, _CONFIDENCE = _o3d._pose_graph_edge_defaults()

    def __init__(self, source_node_id=-1, target_node_id=-1, transformation=None, information=None,
                 uncertain=_UNCERTAIN, confidence=_CONFIDENCE):
        if isinstance(source_node_id, PoseGraphEdge):  # copy constructor
            source_node_id, target_node_id, transformation, information, uncertain, confidence = \
                source_node_id._get()
        self._graph = None
        self._i = -1
        self._values = (int(source_node_id), int(target_node_id),
                        _matrix(self._TRANSFORMATION if transformation is None else transformation, 4,
                                "transformation"),
                        _matrix(self._INFORMATION if information is None else information, 6, "information"),
                        bool(uncertain), float(confidence))

    @classmethod
    def _view(cls, graph, i):
        edge = cls.__new__(cls)
        edge._graph, edge._i, edge._values = graph, i, None
        return edge

    def _get(self):
        return self._graph._get_edge(self._i) if self._graph is not None else self._values

    def _set(self, field, value):
        values = list(self._get())
        values[_EDGE_FIELDS.index(field)] = value
        if self._graph is not None:
            self._graph._set_edge(self._i, *values)
        else:
            self._values = PoseGraphEdge(*values)._values

    def __copy__(self):
        return PoseGraphEdge(*self._get())

    def __deepcopy__(self, memo):
        return PoseGraphEdge(*self._get())

    def __reduce__(self):
        return PoseGraphEdge, tuple(np.array(v) if isinstance(v, np.ndarray) else v for v in self._get())

    def __repr__(self):
        s, t = self._get()[:2]
        return f"PoseGraphEdge from nodes {s} to {t}, access transformation to get relative transformation"


def _edge_property(field, doc):
    k = _EDGE_FIELDS.index(field)
    return property(lambda self: self._get()[k], lambda self, value: self._set(field, value), doc=doc)


PoseGraphEdge.source_node_id = _edge_property("source_node_id", "Index of the source node.")
PoseGraphEdge.target_node_id = _edge_property("target_node_id", "Index of the target node.")
PoseGraphEdge.transformation = _edge_property("transformation", "(4, 4) source frame -> target frame.")
PoseGraphEdge.information = _edge_property("information", "(6, 6) information matrix (rotation first).")
PoseGraphEdge.uncertain = _edge_property("uncertain", "True for a loop closure the line process may prune.")
PoseGraphEdge.confidence = _edge_property("confidence", "Line-process weight in [0, 1].")


class _GraphVector(MutableSequence):
    """A list of nodes or edges: free-standing (its own list) or a view of a graph's."""

    _item = None  # PoseGraphNode or PoseGraphEdge

    def __init__(self, items=()):
        self._graph = None
        self._items = [self._copy(x) for x in items]

    @classmethod
    def _view(cls, graph):
        v = cls.__new__(cls)
        v._graph, v._items = graph, None
        return v

    # how items are stored in a graph (subclasses): _copy(item) -> a free-standing copy, _raw(item) -> values

    def _values(self, graph):  # every entry's raw values
        raise NotImplementedError

    def _rebuild(self, graph, values):  # replace every entry (the C API has no removal)
        raise NotImplementedError

    def __len__(self):
        return len(self._items) if self._graph is None else self._size()

    def __getitem__(self, i):
        if isinstance(i, slice):
            return type(self)(self[j] for j in range(*i.indices(len(self))))
        i = _index(i, len(self))
        return self._items[i] if self._graph is None else self._item._view(self._graph, i)

    def __setitem__(self, i, value):
        if self._graph is None:
            if isinstance(i, slice):
                self._items[i] = [self._copy(x) for x in value]
            else:
                self._items[_index(i, len(self._items))] = self._copy(value)
        elif isinstance(i, slice):
            values = self._values(self._graph)
            values[i] = [self._raw(self._copy(x)) for x in value]
            self._rebuild(self._graph, values)
        else:
            self._put(self._graph, _index(i, len(self)), self._copy(value))

    def __delitem__(self, i):
        if self._graph is None:
            del self._items[i]
            return
        values = self._values(self._graph)
        if not isinstance(i, slice):
            i = _index(i, len(values))
        del values[i]
        self._rebuild(self._graph, values)

    def insert(self, i, value):
        item = self._copy(value)
        if self._graph is None:
            self._items.insert(i, item)
            return
        n = len(self)
        if i >= n:
            self._add(self._graph, item)
            return
        values = self._values(self._graph)
        values.insert(i, self._raw(item))
        self._rebuild(self._graph, values)

    def append(self, value):
        if self._graph is None:
            self._items.append(self._copy(value))
        else:
            self._add(self._graph, self._copy(value))

    def clear(self):
        if self._graph is None:
            self._items.clear()
        else:
            self._rebuild(self._graph, [])

    def __repr__(self):
        return f"{type(self).__name__} with {len(self)} elements."


class PoseGraphNodeVector(_GraphVector):
    """List of PoseGraphNode (pose_graph.nodes)."""

    _item = PoseGraphNode

    @staticmethod
    def _copy(x):
        if not isinstance(x, PoseGraphNode):
            raise TypeError(f"expected a PoseGraphNode, got {type(x).__name__}")
        return PoseGraphNode(x.pose)

    @staticmethod
    def _raw(node):
        return node.pose

    def _size(self):
        return self._graph._num_nodes()

    def _put(self, graph, i, node):
        graph._set_node(i, node.pose)

    def _add(self, graph, node):
        graph._add_node(node.pose)

    def _values(self, graph):
        return [graph._get_node(i) for i in range(graph._num_nodes())]

    def _rebuild(self, graph, poses):
        _rebuild(graph, poses, [graph._get_edge(i) for i in range(graph._num_edges())])


class PoseGraphEdgeVector(_GraphVector):
    """List of PoseGraphEdge (pose_graph.edges)."""

    _item = PoseGraphEdge

    @staticmethod
    def _copy(x):
        if not isinstance(x, PoseGraphEdge):
            raise TypeError(f"expected a PoseGraphEdge, got {type(x).__name__}")
        return PoseGraphEdge(*x._get())

    @staticmethod
    def _raw(edge):
        return edge._get()

    def _size(self):
        return self._graph._num_edges()

    def _put(self, graph, i, edge):
        graph._set_edge(i, *edge._get())

    def _add(self, graph, edge):
        graph._add_edge(*edge._get())

    def _values(self, graph):
        return [graph._get_edge(i) for i in range(graph._num_edges())]

    def _rebuild(self, graph, edges):
        _rebuild(graph, [graph._get_node(i) for i in range(graph._num_nodes())], edges)


def _rebuild(graph, poses, edges):
    # Validate everything first (a copy takes the new contents), then swap it in, so a bad entry leaves
    # the graph as it was.
    trial = _o3d.PoseGraph()
    for pose in poses:
        trial._add_node(pose)
    for edge in edges:
        trial._add_edge(*edge)
    graph._clear()
    for pose in poses:
        graph._add_node(pose)
    for edge in edges:
        graph._add_edge(*edge)


def _nodes(self):
    return PoseGraphNodeVector._view(self)


def _set_nodes(self, nodes):
    if isinstance(nodes, _GraphVector) and nodes._graph is self:
        return
    PoseGraphNodeVector._view(self)._rebuild(self, [PoseGraphNodeVector._raw(PoseGraphNodeVector._copy(n))
                                                    for n in nodes])


def _edges(self):
    return PoseGraphEdgeVector._view(self)


def _set_edges(self, edges):
    if isinstance(edges, _GraphVector) and edges._graph is self:
        return
    PoseGraphEdgeVector._view(self)._rebuild(self, [PoseGraphEdgeVector._raw(PoseGraphEdgeVector._copy(e))
                                                    for e in edges])


_o3d.PoseGraph.nodes = property(_nodes, _set_nodes, doc="The nodes (PoseGraphNodeVector, a view of the graph).")
_o3d.PoseGraph.edges = property(_edges, _set_edges, doc="The edges (PoseGraphEdgeVector, a view of the graph).")


def _pose_graph_reduce(self):
    return _pose_graph_from_state, ([np.array(n.pose) for n in self.nodes],
                                    [tuple(np.array(v) if isinstance(v, np.ndarray) else v for v in e._get())
                                     for e in self.edges])


def _pose_graph_from_state(poses, edges):
    graph = _o3d.PoseGraph()
    _rebuild(graph, poses, edges)
    return graph


_o3d.PoseGraph.__reduce__ = _pose_graph_reduce
