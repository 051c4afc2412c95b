"""The process: the thread pool (:mod:`.threadpool`), start-up and Ctrl-C handling
(:mod:`.startup`), and memory kept between frames or handed back to the OS (:mod:`.memory`)."""
