"""Pure vectorised plane geometry: arrays of shape (N, 2) for points, (N,) for scalars."""
