// Placeholder: replaced by the real sources of this part.
