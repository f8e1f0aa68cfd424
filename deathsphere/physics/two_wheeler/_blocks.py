"""The generated equations' runtime: a batch's shape and dtype, and the
evaluation of a function over a large batch in blocks (beyond the paper;
docs/two-wheeler.md sec. 5).  ``_generated.py`` imports these; the code
generator (``deathsphere.codegen``) writes only the functions that use them.
"""

import functools
import math

import numpy

__all__ = ["BLOCK_BYTES", "batch", "in_blocks"]

#: Bytes of each temporary per block of the batch: a function's thousand
#: temporaries then stay in the processor's cache, which halves the time per
#: state of a large batch.
BLOCK_BYTES = 32768


def batch(*arrays):
    """The broadcast batch shape and result dtype of the arguments (beyond
    the paper; docs/two-wheeler.md sec. 5)."""
    arrays = [a for a in arrays if not isinstance(a, (float, int))]
    shape = numpy.broadcast_shapes(*(numpy.shape(a)[1:] if numpy.ndim(a) else () for a in arrays))
    return shape, numpy.result_type(float, *arrays)


def in_blocks(rows):
    """Evaluate a function of (``rows`` arrays (k, *batch), p, then arguments
    per state) over its batch in blocks of BLOCK_BYTES per temporary, the
    outputs joined along the batch (beyond the paper; docs/two-wheeler.md
    sec. 5)."""
    def decorate(function):
        @functools.wraps(function)
        def blocked(*args):
            arrays, p, columns = [numpy.asarray(a) for a in args[:rows]], args[rows], args[rows + 1:]
            others = [x for x in (*p, *columns) if not isinstance(x, (float, int))]
            batch = numpy.broadcast_shapes(*(a.shape[1:] for a in arrays), *(numpy.shape(x) for x in others))
            size = math.prod(batch)
            block = max(BLOCK_BYTES // numpy.result_type(float, *arrays, *others).itemsize, 1)
            if size <= block:
                return function(*args)
            arrays = [numpy.broadcast_to(a, a.shape[:1] + batch).reshape(-1, size) for a in arrays]
            # the arguments that vary along the batch, flattened, and those that do not
            p, columns = ([(x, False) if numpy.ndim(x) == 0 else (numpy.broadcast_to(x, batch).reshape(size), True)
                           for x in xs] for xs in (p, columns))
            parts = []
            for start in range(0, size, block):
                cut = slice(start, start + block)
                parts.append(function(*(a[:, cut] for a in arrays), tuple(x[cut] if varies else x for x, varies in p),
                                      *(x[cut] if varies else x for x, varies in columns)))
            if not isinstance(parts[0], tuple):
                return numpy.concatenate(parts, axis=-1).reshape(parts[0].shape[:-1] + batch)
            return tuple(numpy.concatenate(out, axis=-1).reshape(out[0].shape[:-1] + batch) for out in zip(*parts))
        return blocked
    return decorate
