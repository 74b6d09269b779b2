// The perception experiment of stochtex (thesis section 2.6.2), run by the
// page that studies/stimuli.cpp writes: for each trial, in the order baked
// into the page, a mean-grey screen for resetMs, the stimulus for durationMs,
// grey again and the question "repeating pattern: yes / no" (keys Y / N or
// the buttons). At the end the answers are offered as a CSV download and
// shown in a <pre>.
//
// Automated mode, for tests: experiment.html#auto=yyn... presses Space to
// start and then the scripted keys, one per question, by dispatching real
// keydown events on document (the handler real key presses reach), with
// short timings; the CSV lands in the DOM as in a real run.
(function () {
    'use strict';
    var config = JSON.parse(document.getElementById('experiment-config').textContent);
    var trials = config.trials;
    var match = /(?:^#|&)auto=([yn]*)/.exec(window.location.hash);
    var script = match ? match[1] : null;
    var durationMs = script !== null ? 20 : config.durationMs;
    var resetMs = script !== null ? 20 : config.resetMs;

    var $ = function (id) { return document.getElementById(id); };
    // The stimuli are <img> elements of the page (loaded before its load
    // event), one per trial in the order shown.
    var images = trials.map(function (t) { return $('stimulus-' + t.trial); });
    var loaded = false;
    var state = 'intro';
    var index = 0;
    var questionShownAt = 0;
    var shownMs = 0;
    var rows = [];

    // One image pixel per device pixel: the stimulus is not rescaled.
    function fitImages() {
        var side = (config.size / (window.devicePixelRatio || 1)) + 'px';
        images.forEach(function (image) {
            image.style.width = side;
            image.style.height = side;
        });
    }

    function setState(s) {
        state = s;
        document.body.setAttribute('data-state', s);
        $('intro').hidden = s !== 'intro';
        $('question').hidden = s !== 'question';
        $('done').hidden = s !== 'done';
        if (index < images.length) images[index].style.visibility = s === 'stimulus' ? 'visible' : 'hidden';
        if (s === 'question' && script !== null) {
            var key = script.charAt(index);
            if (key) setTimeout(function () { press(key); }, 5);
        }
    }

    // A real keydown event on document: the automated mode's keys take the
    // same path as the keyboard's.
    function press(key) {
        document.dispatchEvent(new KeyboardEvent('keydown', { key: key, bubbles: true, cancelable: true }));
    }

    function wait(ms) { return new Promise(function (resolve) { setTimeout(resolve, ms); }); }

    function runTrial() {
        var image = images[index];
        setState('reset');
        image.style.display = 'block';
        wait(resetMs).then(function () {
            setState('stimulus');
            var shownAt = performance.now();
            return wait(durationMs).then(function () {
                setState('reset');
                shownMs = performance.now() - shownAt;
                image.style.display = 'none';
                $('progress').textContent = 'Trial ' + (index + 1) + ' of ' + trials.length;
                questionShownAt = performance.now();
                setState('question');
            });
        });
    }

    function csvText() {
        var header = 'trial,stimulus,w,correlation,alpha,answer,response_time_ms,shown_ms';
        return [header].concat(rows).join('\n') + '\n';
    }

    function finish() {
        var csv = csvText();
        $('answers-csv').textContent = csv;
        $('download').href = 'data:text/csv;charset=utf-8,' + encodeURIComponent(csv);
        setState('done');
    }

    function answer(yes) {
        if (state !== 'question') return;
        var trial = trials[index];
        var responseMs = performance.now() - questionShownAt;
        rows.push([trial.trial, trial.stimulus, trial.w, trial.correlation, Number(trial.alpha.toPrecision(6)),
                   yes ? 'yes' : 'no', Math.round(responseMs), Math.round(shownMs)].join(','));
        index += 1;
        if (index < trials.length) runTrial(); else finish();
    }

    function start() {
        if (state !== 'intro' || !loaded) return;
        if (trials.length === 0) finish(); else runTrial();
    }

    document.addEventListener('keydown', function (event) {
        if (event.repeat) return;  // a held key answers one question, not the next ones too
        var key = (event.key || '').toLowerCase();
        if (state === 'intro' && (key === ' ' || key === 'enter')) {
            event.preventDefault();
            start();
        } else if (state === 'question' && (key === 'y' || key === 'n')) {
            event.preventDefault();
            answer(key === 'y');
        }
    });
    $('start').addEventListener('click', start);
    $('yes').addEventListener('click', function () { answer(true); });
    $('no').addEventListener('click', function () { answer(false); });
    window.addEventListener('resize', fitImages);
    window.addEventListener('load', function () {
        loaded = true;
        $('start').disabled = false;
        if (script !== null) setTimeout(function () { press(' '); }, 5);
    });
    fitImages();
    setState('intro');
})();
