/// The source that builds the tests' precompiled header (pch.hpp); it defines nothing.
