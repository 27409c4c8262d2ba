"""The module's exceptions: a scene that cannot be simulated, a run that stopped."""
import re

__all__ = ["SceneError", "SimulationError"]

# "<field>: <reason>", where a field is a path in the scene file such as
# blocks[3].vertices[2] or contact.kn ("near <field>" for JSON syntax errors).
_FIELD = re.compile(r"^((?:near )?[A-Za-z_][A-Za-z0-9_]*(?:\[\d+\])*(?:\.[A-Za-z_][A-Za-z0-9_]*(?:\[\d+\])*)*): (.*)$",
                    re.S)
_POSITION = re.compile(r"^:(\d+):(\d+)(?=: )")


class SceneError(ValueError):
    """A scene the library refuses, with the message `dda check` prints.

    Attributes:
      source: the file path, "<string>" or "<scene>" (a dict or a scene built in Python)
      field:  the path of the field in the scene document, e.g. "blocks[3].vertices[2]"
              (None when the error is about the whole file)
      line, column: 1-based position of the field in the JSON text (file and string
              sources; None for dicts and built scenes, and where the field is not in
              the text: a missing key, a generated block)
      reason: what is wrong
    """

    def __init__(self, message, source=None, field=None, line=None, column=None, reason=None):
        super().__init__(message)
        self.source = source
        self.field = field
        self.line = line
        self.column = column
        self.reason = reason if reason is not None else message

    @classmethod
    def from_library(cls, message, source, positions=True):
        """The library's message "<source>[:<line>:<col>]: [<field>: ]<reason>" as a SceneError.
        positions=False drops the line and column (they point into a text the
        user never saw: the JSON made from a dict or a built scene)."""
        rest = message[len(source):] if message.startswith(source) else message
        line = column = None
        m = _POSITION.match(rest)
        if m:
            line, column = int(m.group(1)), int(m.group(2))
            rest = rest[m.end():]
        if rest.startswith(": "):
            rest = rest[2:]
        field, reason = None, rest
        m = _FIELD.match(rest)
        if m:
            field, reason = m.group(1), m.group(2)
            if field.startswith("near "):
                field = field[5:]
        if not positions:
            line = column = None
            message = f"{source}: {field}: {reason}" if field else f"{source}: {reason}"
        return cls(message, source=source, field=field, line=line, column=column, reason=reason)

    def __reduce__(self):  # picklable with its attributes
        return (type(self), (str(self), self.source, self.field, self.line, self.column, self.reason))


class SimulationError(RuntimeError):
    """A run stopped by a guard of the library (the method's domain was left).

    Attributes:
      reason: the guard, one of "non_finite", "area_collapsed", "step_motion",
              "energy_growth", "energy_budget", "penetration", "approach_energy", "other"
      step, time: the step that failed and its time, s (None if not known)
      block: the block named (None if none)
      pair: (a, b) the pair named, a < b (None if none)

    The simulation stays at the failed step's state: it can be read (its
    time is `time`), not trusted to step on.
    """

    def __init__(self, message, reason="other", step=None, time=None, block=None, pair=None):
        super().__init__(message)
        self.reason = reason
        self.step = step
        self.time = time
        self.block = block
        self.pair = pair

    def __reduce__(self):  # picklable with its attributes (sweeps send it between processes)
        return (type(self), (str(self), self.reason, self.step, self.time, self.block, self.pair))
