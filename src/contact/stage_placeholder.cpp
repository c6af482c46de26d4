// Placeholder so the stage library has a translation unit until its first source lands.
