<?xml version='1.0' encoding='utf-8'?>
<TS version="2.1" language="de">
<context>
    <name>Cli</name>
    <message>
        <source>Write the rows as JSON to &lt;file&gt;.</source>
        <translation>Die Zeilen als JSON in &lt;file&gt; schreiben.</translation>
    </message>
    <message>
        <source>Draw the curves to the PNG &lt;file&gt;.</source>
        <translation>Die Kurven in die PNG-Datei &lt;file&gt; zeichnen.</translation>
    </message>
    <message>
        <source>Smaller sizes and fewer repetitions.</source>
        <translation>Kleinere Größen und weniger Wiederholungen.</translation>
    </message>
    <message>
        <source>List the benchmarks.</source>
        <translation>Die Benchmarks auflisten.</translation>
    </message>
    <message>
        <source>Show this help.</source>
        <translation>Diese Hilfe anzeigen.</translation>
    </message>
    <message>
        <source>The benchmark to run.</source>
        <translation>Der auszuführende Benchmark.</translation>
    </message>
    <message>
        <source>Usage: microsim-cli bench NAME [--json FILE] [--plot FILE.png] [--quick]</source>
        <translation>Aufruf: microsim-cli bench NAME [--json DATEI] [--plot DATEI.png] [--quick]</translation>
    </message>
    <message>
        <source>Benchmarks:</source>
        <translation>Benchmarks:</translation>
    </message>
    <message>
        <source>run a benchmark (beside the paper's figures)</source>
        <translation>einen Benchmark ausführen (neben den Werten des Artikels)</translation>
    </message>
    <message>
        <source>Usage: microsim-cli &lt;command&gt; [options]</source>
        <translation>Aufruf: microsim-cli &lt;Befehl&gt; [Optionen]</translation>
    </message>
    <message>
        <source>       microsim-cli --version | --help</source>
        <translation>       microsim-cli --version | --help</translation>
    </message>
    <message>
        <source>Commands:</source>
        <translation>Befehle:</translation>
    </message>
    <message>
        <source>Run 'microsim-cli &lt;command&gt; --help' for a command's options.</source>
        <translation>„microsim-cli &lt;Befehl&gt; --help“ zeigt die Optionen eines Befehls.</translation>
    </message>
    <message>
        <source>microsim-cli: unknown command '%1'</source>
        <translation>microsim-cli: unbekannter Befehl „%1“</translation>
    </message>
    <message>
        <source>solve a spring network (scene file or lattice box)</source>
        <translation>ein Federnetz lösen (Szenendatei oder Gitterwürfel)</translation>
    </message>
    <message>
        <source>export the spring network a scene builds</source>
        <translation>das Federnetz exportieren, das eine Szene erzeugt</translation>
    </message>
    <message>
        <source>Write the network as JSON to &lt;file&gt;.</source>
        <translation>Das Netz als JSON in &lt;file&gt; schreiben.</translation>
    </message>
    <message>
        <source>Usage: microsim-cli export --scene FILE | --lattice N [--json FILE]</source>
        <translation>Aufruf: microsim-cli export --scene DATEI | --lattice N [--json DATEI]</translation>
    </message>
    <message>
        <source>unexpected argument '%1'</source>
        <translation>unerwartetes Argument „%1“</translation>
    </message>
    <message>
        <source>objects</source>
        <translation>Objekte</translation>
    </message>
    <message>
        <source>nodes</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <source>links</source>
        <translation>Federn</translation>
    </message>
    <message>
        <source>fixed</source>
        <translation>fest</translation>
    </message>
    <message>
        <source>controls</source>
        <translation>Steuerknoten</translation>
    </message>
    <message>
        <source>triangles</source>
        <translation>Dreiecke</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>converged</source>
        <translation>konvergiert</translation>
    </message>
    <message>
        <source>iteration limit</source>
        <translation>Iterationsgrenze</translation>
    </message>
    <message>
        <source>time limit</source>
        <translation>Zeitgrenze</translation>
    </message>
    <message>
        <source>diverged (state restored)</source>
        <translation>divergiert (Zustand wiederhergestellt)</translation>
    </message>
    <message>
        <source>invalid input</source>
        <translation>ungültige Eingabe</translation>
    </message>
    <message>
        <source>--%1 wants a number in [%2, %3), not '%4'</source>
        <translation>--%1 erwartet eine Zahl in [%2, %3), nicht „%4“</translation>
    </message>
    <message>
        <source>The solver: %1 (default: the scene's, else qss).</source>
        <translation>Der Löser: %1 (Vorgabe: der der Szene, sonst qss).</translation>
    </message>
    <message>
        <source>Stop after &lt;k&gt; iterations.</source>
        <translation>Nach &lt;k&gt; Iterationen anhalten.</translation>
    </message>
    <message>
        <source>Stop after &lt;t&gt; milliseconds of wall-clock time.</source>
        <translation>Nach &lt;t&gt; Millisekunden Echtzeit anhalten.</translation>
    </message>
    <message>
        <source>qss per-level cutout ε in mm (0 = off).</source>
        <translation>qss-Abbruchschwelle ε je Ebene in mm (0 = aus).</translation>
    </message>
    <message>
        <source>qss step scale in mm per force unit (0 = automatic).</source>
        <translation>qss-Schrittweite in mm je Krafteinheit (0 = automatisch).</translation>
    </message>
    <message>
        <source>qss momentum β in [0, 1).</source>
        <translation>qss-Impuls β in [0, 1).</translation>
    </message>
    <message>
        <source>Stop once the relative residual is below &lt;r&gt;.</source>
        <translation>Anhalten, sobald das relative Residuum unter &lt;r&gt; liegt.</translation>
    </message>
    <message>
        <source>Write positions and the report as JSON to &lt;file&gt;.</source>
        <translation>Positionen und Bericht als JSON in &lt;file&gt; schreiben.</translation>
    </message>
    <message>
        <source>Usage: microsim-cli solve --scene FILE | --lattice N [--solver NAME] (--iterations K | --budget-ms T) [options]</source>
        <translation>Aufruf: microsim-cli solve --scene DATEI | --lattice N [--solver NAME] (--iterations K | --budget-ms T) [Optionen]</translation>
    </message>
    <message>
        <source>--iterations wants a whole number ≥ 1, not '%1'</source>
        <translation>--iterations erwartet eine ganze Zahl ≥ 1, nicht „%1“</translation>
    </message>
    <message>
        <source>unknown solver '%1' (known: %2)</source>
        <translation>unbekannter Löser „%1“ (bekannt: %2)</translation>
    </message>
    <message>
        <source>the scene names an unknown solver '%1'</source>
        <translation>die Szene nennt einen unbekannten Löser „%1“</translation>
    </message>
    <message>
        <source>give --iterations K or --budget-ms T (or put them in the scene's "solver")</source>
        <translation>--iterations K oder --budget-ms T angeben (oder im „solver“ der Szene festlegen)</translation>
    </message>
    <message>
        <source>solver</source>
        <translation>Löser</translation>
    </message>
    <message>
        <source>iterations</source>
        <translation>Iterationen</translation>
    </message>
    <message>
        <source>seconds</source>
        <translation>Sekunden</translation>
    </message>
    <message>
        <source>residual</source>
        <translation>Residuum</translation>
    </message>
    <message>
        <source>status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>cannot open the scene file</source>
        <translation>die Szenendatei kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>not valid JSON</source>
        <translation>kein gültiges JSON</translation>
    </message>
    <message>
        <source>wrong type or length</source>
        <translation>falscher Typ oder falsche Länge</translation>
    </message>
    <message>
        <source>required field missing</source>
        <translation>Pflichtfeld fehlt</translation>
    </message>
    <message>
        <source>unknown field</source>
        <translation>unbekanntes Feld</translation>
    </message>
    <message>
        <source>unknown object type</source>
        <translation>unbekannter Objekttyp</translation>
    </message>
    <message>
        <source>node index out of range</source>
        <translation>Knotenindex außerhalb des Bereichs</translation>
    </message>
    <message>
        <source>link joins a node to itself</source>
        <translation>Feder verbindet einen Knoten mit sich selbst</translation>
    </message>
    <message>
        <source>value must not be negative</source>
        <translation>Wert darf nicht negativ sein</translation>
    </message>
    <message>
        <source>number is not finite</source>
        <translation>Zahl ist nicht endlich</translation>
    </message>
    <message>
        <source>node is controlled twice</source>
        <translation>Knoten wird doppelt gesteuert</translation>
    </message>
    <message>
        <source>value out of range</source>
        <translation>Wert außerhalb des Bereichs</translation>
    </message>
    <message>
        <source>cannot import the surface mesh</source>
        <translation>das Oberflächennetz kann nicht importiert werden</translation>
    </message>
    <message>
        <source>file not found</source>
        <translation>Datei nicht gefunden</translation>
    </message>
    <message>
        <source>unreadable</source>
        <translation>unlesbar</translation>
    </message>
    <message>
        <source>no triangles</source>
        <translation>keine Dreiecke</translation>
    </message>
    <message>
        <source>non-finite coordinates</source>
        <translation>nicht endliche Koordinaten</translation>
    </message>
    <message>
        <source>bad import options</source>
        <translation>ungültige Importoptionen</translation>
    </message>
    <message>
        <source>(field %1)</source>
        <translation>(Feld %1)</translation>
    </message>
    <message>
        <source>give exactly one of --scene FILE and --lattice N</source>
        <translation>genau eines von --scene DATEI und --lattice N angeben</translation>
    </message>
    <message>
        <source>--stiffness applies to --lattice only</source>
        <translation>--stiffness gilt nur für --lattice</translation>
    </message>
    <message>
        <source>--lattice wants a whole number from 2 to 200, not '%1'</source>
        <translation>--lattice erwartet eine ganze Zahl von 2 bis 200, nicht „%1“</translation>
    </message>
    <message>
        <source>--stiffness wants a number ≥ 0, not '%1'</source>
        <translation>--stiffness erwartet eine Zahl ≥ 0, nicht „%1“</translation>
    </message>
    <message>
        <source>Read the spring network from the scene &lt;file&gt;.</source>
        <translation>Das Federnetz aus der Szene &lt;file&gt; lesen.</translation>
    </message>
    <message>
        <source>Use the paper's N×N×N lattice box (bottom fixed, top middle node pulled up 1 mm).</source>
        <translation>Den N×N×N-Gitterwürfel des Artikels verwenden (Boden fest, mittlerer Knoten oben 1 mm nach oben gezogen).</translation>
    </message>
    <message>
        <source>Link stiffness of the --lattice box in g/s² (default 10).</source>
        <translation>Federsteifigkeit des --lattice-Würfels in g/s² (Vorgabe 10).</translation>
    </message>
    <message>
        <source>each pose must be 16 numbers (a 4 by 4 matrix, row-major)</source>
        <translation>jede Pose muss aus 16 Zahlen bestehen (eine 4×4-Matrix, zeilenweise)</translation>
    </message>
    <message>
        <source>each fiducial and check point needs "tracker" and "scene" as [x, y, z]</source>
        <translation>jeder Referenz- und Prüfpunkt braucht „tracker“ und „scene“ als [x, y, z]</translation>
    </message>
    <message>
        <source>Read the poses or points from the JSON &lt;file&gt;.</source>
        <translation>Die Posen oder Punkte aus der JSON-Datei &lt;file&gt; lesen.</translation>
    </message>
    <message>
        <source>Write the result as JSON to &lt;file&gt;.</source>
        <translation>Das Ergebnis als JSON in &lt;file&gt; schreiben.</translation>
    </message>
    <message>
        <source>pivot or register</source>
        <translation>pivot oder register</translation>
    </message>
    <message>
        <source>run a scene on recorded or scripted input (hash, events, timings)</source>
        <translation>eine Szene mit aufgezeichneter oder geskripteter Eingabe ausführen (Hash, Ereignisse, Zeiten)</translation>
    </message>
    <message>
        <source>record what an OpenIGTLink tracker sends</source>
        <translation>aufzeichnen, was ein OpenIGTLink-Tracker sendet</translation>
    </message>
    <message>
        <source>pivot calibration or tracker-to-scene registration from a file</source>
        <translation>Pivot-Kalibrierung oder Tracker-Szene-Registrierung aus einer Datei</translation>
    </message>
    <message numerus="yes">
        <source>forceps grabs %n tissue node(s)</source>
        <translation><numerusform>Pinzette greift %n Gewebeknoten</numerusform><numerusform>Pinzette greift %n Gewebeknoten</numerusform></translation>
    </message>
    <message numerus="yes">
        <source>forceps releases %n tissue node(s)</source>
        <translation><numerusform>Pinzette lässt %n Gewebeknoten los</numerusform><numerusform>Pinzette lässt %n Gewebeknoten los</numerusform></translation>
    </message>
    <message>
        <source>forceps grips the suture at node %1</source>
        <translation>Pinzette fasst den Faden an Knoten %1</translation>
    </message>
    <message>
        <source>forceps lets go of the suture</source>
        <translation>Pinzette lässt den Faden los</translation>
    </message>
    <message>
        <source>needle enters a wall</source>
        <translation>Nadel tritt in eine Wand ein</translation>
    </message>
    <message>
        <source>needle leaves a wall</source>
        <translation>Nadel tritt aus einer Wand aus</translation>
    </message>
    <message numerus="yes">
        <source>scalpel cuts %n link(s)</source>
        <translation><numerusform>Skalpell durchtrennt %n Feder</numerusform><numerusform>Skalpell durchtrennt %n Federn</numerusform></translation>
    </message>
    <message>
        <source>suture breaks at link %1</source>
        <translation>Faden reißt an Glied %1</translation>
    </message>
    <message>
        <source>suture slips out of a pierce</source>
        <translation>Faden rutscht aus einem Durchstich</translation>
    </message>
    <message>
        <source>needle leaves a pierce before the thread reaches it</source>
        <translation>Nadel verlässt einen Durchstich, bevor der Faden ihn erreicht</translation>
    </message>
    <message>
        <source>input frame rejected</source>
        <translation>Eingabebild verworfen</translation>
    </message>
    <message>
        <source>cannot open the recording</source>
        <translation>die Aufzeichnung kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>cannot write the recording</source>
        <translation>die Aufzeichnung kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>not a microsim recording</source>
        <translation>keine microsim-Aufzeichnung</translation>
    </message>
    <message>
        <source>recording from a newer version</source>
        <translation>Aufzeichnung einer neueren Version</translation>
    </message>
    <message>
        <source>unfinished recording (no end record)</source>
        <translation>unvollständige Aufzeichnung (kein Abschlusseintrag)</translation>
    </message>
    <message>
        <source>damaged recording (checksum mismatch)</source>
        <translation>beschädigte Aufzeichnung (Prüfsumme stimmt nicht)</translation>
    </message>
    <message>
        <source>damaged recording (malformed frame)</source>
        <translation>beschädigte Aufzeichnung (fehlerhaftes Bild)</translation>
    </message>
    <message>
        <source>Replay the input frames of the recording &lt;file&gt;.</source>
        <translation>Die Eingabebilder der Aufzeichnung &lt;file&gt; abspielen.</translation>
    </message>
    <message>
        <source>Generate the input instead: 'stitch' (one scripted stitch) or 'back-wall-catch' (a pass that catches the back wall).</source>
        <translation>Stattdessen die Eingabe erzeugen: „stitch“ (eine geskriptete Naht) oder „back-wall-catch“ (ein Stich, der die Hinterwand fasst).</translation>
    </message>
    <message>
        <source>Record every input frame to &lt;file&gt;.</source>
        <translation>Jedes Eingabebild in &lt;file&gt; aufzeichnen.</translation>
    </message>
    <message>
        <source>Run &lt;n&gt; steps (default: every input frame, else 100).</source>
        <translation>&lt;n&gt; Schritte ausführen (Vorgabe: jedes Eingabebild, sonst 100).</translation>
    </message>
    <message>
        <source>Stop each tissue solve at the step budget (not reproducible).</source>
        <translation>Jede Gewebelösung am Schrittbudget anhalten (nicht reproduzierbar).</translation>
    </message>
    <message>
        <source>Write the hash, events and timings as JSON to &lt;file&gt;.</source>
        <translation>Hash, Ereignisse und Zeiten als JSON in &lt;file&gt; schreiben.</translation>
    </message>
    <message>
        <source>--input and --script exclude each other</source>
        <translation>--input und --script schließen einander aus</translation>
    </message>
    <message>
        <source>unknown script '%1' (known: %2)</source>
        <translation>unbekanntes Skript „%1“ (bekannt: %2)</translation>
    </message>
    <message>
        <source>--frames wants a whole number ≥ 0, not '%1'</source>
        <translation>--frames erwartet eine ganze Zahl ≥ 0, nicht „%1“</translation>
    </message>
    <message numerus="yes">
        <source>replaying its %n complete frame(s)</source>
        <translation><numerusform>es wird sein %n vollständiges Bild abgespielt</numerusform><numerusform>es werden seine %n vollständigen Bilder abgespielt</numerusform></translation>
    </message>
    <message>
        <source>(at byte %1)</source>
        <translation>(bei Byte %1)</translation>
    </message>
    <message>
        <source>the script '%1' needs a severed vessel, a curved needle and two forceps</source>
        <translation>das Skript „%1“ braucht ein durchtrenntes Gefäß, eine gebogene Nadel und zwei Pinzetten</translation>
    </message>
    <message>
        <source>scene</source>
        <translation>Szene</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>Schritte</translation>
    </message>
    <message>
        <source> of %1 s</source>
        <translation> von %1 s</translation>
    </message>
    <message>
        <source>state hash</source>
        <translation>Zustands-Hash</translation>
    </message>
    <message>
        <source>events</source>
        <translation>Ereignisse</translation>
    </message>
    <message>
        <source>end %1, angle %2°, bite %3 mm, at (%4, %5, %6)</source>
        <translation>Ende %1, Winkel %2°, Stichabstand %3 mm, bei (%4, %5, %6)</translation>
    </message>
    <message>
        <source>collision</source>
        <translation>Kollision</translation>
    </message>
    <message>
        <source>tissue</source>
        <translation>Gewebe</translation>
    </message>
    <message>
        <source>suture</source>
        <translation>Faden</translation>
    </message>
    <message>
        <source>interactions</source>
        <translation>Interaktionen</translation>
    </message>
    <message>
        <source>total</source>
        <translation>gesamt</translation>
    </message>
    <message>
        <source>step time (ms)</source>
        <translation>Schrittzeit (ms)</translation>
    </message>
    <message>
        <source>median</source>
        <translation>Median</translation>
    </message>
    <message>
        <source>p99</source>
        <translation>p99</translation>
    </message>
    <message>
        <source>max</source>
        <translation>Max.</translation>
    </message>
    <message>
        <source>OpenIGTLink server to read, HOST:PORT (port 18944 by default).</source>
        <translation>Zu lesender OpenIGTLink-Server, HOST:PORT (Vorgabe Port 18944).</translation>
    </message>
    <message>
        <source>Record for &lt;seconds&gt; (default 10).</source>
        <translation>&lt;seconds&gt; Sekunden lang aufzeichnen (Vorgabe 10).</translation>
    </message>
    <message>
        <source>Write the record as JSON to &lt;file&gt;.</source>
        <translation>Die Aufzeichnung als JSON in &lt;file&gt; schreiben.</translation>
    </message>
    <message>
        <source>Stop when the server closes the link (no reconnection).</source>
        <translation>Anhalten, wenn der Server die Verbindung schließt (keine Neuverbindung).</translation>
    </message>
    <message>
        <source>Refuse poses moving faster than &lt;mm/s&gt; (default 2000).</source>
        <translation>Posen verwerfen, die sich schneller als &lt;mm/s&gt; bewegen (Vorgabe 2000).</translation>
    </message>
    <message>
        <source>%1 connection(s) to %2:%3</source>
        <translation>%1 Verbindung(en) zu %2:%3</translation>
    </message>
    <message>
        <source>device              received   rate (Hz)   last position (mm)</source>
        <translation>Gerät               empfangen  Rate (Hz)   letzte Position (mm)</translation>
    </message>
    <message>
        <source>rejected: %1</source>
        <translation>verworfen: %1</translation>
    </message>
    <message>
        <source>sample %1 of the tracker stream: bad "%2"</source>
        <translation>Wert %1 des Trackerstroms: fehlerhaftes „%2“</translation>
    </message>
    <message>
        <source>not a tracker stream this version reads</source>
        <translation>kein Trackerstrom, den diese Version liest</translation>
    </message>
    <message>
        <source>choose the device with --device (the stream holds: %1)</source>
        <translation>wählen Sie das Gerät mit --device (der Strom enthält: %1)</translation>
    </message>
    <message>
        <source>pivot on a tracker stream: the device to calibrate.</source>
        <translation>pivot auf einem Trackerstrom: das zu kalibrierende Gerät.</translation>
    </message>
    <message>
        <source>Usage: microsim-cli calibrate pivot|register --input FILE [--device NAME] [--json FILE]</source>
        <translation>Aufruf: microsim-cli calibrate pivot|register --input DATEI [--device NAME] [--json DATEI]</translation>
    </message>
    <message>
        <source>score a recorded attempt with a rubric (and store it in the history)</source>
        <translation>einen aufgezeichneten Versuch nach einem Bewertungsschema bewerten (und im Verlauf speichern)</translation>
    </message>
    <message>
        <source>the history database: migrate, backup, restore, export CSV, trainees</source>
        <translation>die Verlaufsdatenbank: migrieren, sichern, wiederherstellen, CSV exportieren, Trainees</translation>
    </message>
    <message>
        <source>cannot create the folder for %1</source>
        <translation>der Ordner für %1 kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>cannot open %1</source>
        <translation>%1 kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>%1 is not a microsim database or is damaged; it was left untouched</source>
        <translation>%1 ist keine microsim-Datenbank oder ist beschädigt; sie wurde nicht verändert</translation>
    </message>
    <message>
        <source>%1 is locked by another program</source>
        <translation>%1 ist von einem anderen Programm gesperrt</translation>
    </message>
    <message>
        <source>%1 was written by a newer microsim</source>
        <translation>%1 wurde von einer neueren microsim-Version geschrieben</translation>
    </message>
    <message>
        <source>updating %1 failed; it was left as it was</source>
        <translation>die Aktualisierung von %1 ist fehlgeschlagen; die Datei blieb unverändert</translation>
    </message>
    <message>
        <source>%1 is read-only; it was left untouched</source>
        <translation>%1 ist schreibgeschützt; die Datei wurde nicht verändert</translation>
    </message>
    <message>
        <source>the database is not open</source>
        <translation>die Datenbank ist nicht geöffnet</translation>
    </message>
    <message>
        <source>not allowed for this user</source>
        <translation>für diesen Benutzer nicht erlaubt</translation>
    </message>
    <message>
        <source>no such person or attempt</source>
        <translation>diese Person oder dieser Versuch existiert nicht</translation>
    </message>
    <message>
        <source>the attempt is already finished</source>
        <translation>der Versuch ist bereits abgeschlossen</translation>
    </message>
    <message>
        <source>that name is taken</source>
        <translation>dieser Name ist bereits vergeben</translation>
    </message>
    <message>
        <source>empty name, or a password shorter than %1 characters</source>
        <translation>leerer Name oder ein Passwort mit weniger als %1 Zeichen</translation>
    </message>
    <message>
        <source>unknown instructor or wrong password</source>
        <translation>unbekannter Ausbilder oder falsches Passwort</translation>
    </message>
    <message>
        <source>not possible on a PostgreSQL server (use pg_dump and pg_restore there)</source>
        <translation>auf einem PostgreSQL-Server nicht möglich (dort pg_dump und pg_restore verwenden)</translation>
    </message>
    <message>
        <source>the file is not a microsim history</source>
        <translation>die Datei ist keine microsim-Verlaufsdatenbank</translation>
    </message>
    <message>
        <source>the backup was written by a newer microsim</source>
        <translation>die Sicherung wurde von einer neueren microsim-Version geschrieben</translation>
    </message>
    <message>
        <source>the database reported an error</source>
        <translation>die Datenbank meldete einen Fehler</translation>
    </message>
    <message>
        <source>instructor</source>
        <translation>Ausbilder</translation>
    </message>
    <message>
        <source>trainee</source>
        <translation>Trainee</translation>
    </message>
    <message>
        <source>The history: an SQLite &lt;file&gt; or a postgresql://user@host:port/db URL.</source>
        <translation>Der Verlauf: eine SQLite-Datei &lt;file&gt; oder eine URL postgresql://user@host:port/db.</translation>
    </message>
    <message>
        <source>add-trainee: the trainee's &lt;group&gt;.</source>
        <translation>add-trainee: die Gruppe &lt;group&gt; des Trainees.</translation>
    </message>
    <message>
        <source>export-csv: sign in as instructor &lt;name&gt; (password on stdin).</source>
        <translation>export-csv: als Ausbilder &lt;name&gt; anmelden (Passwort über stdin).</translation>
    </message>
    <message>
        <source>add-instructor: read the password from standard input.</source>
        <translation>add-instructor: das Passwort von der Standardeingabe lesen.</translation>
    </message>
    <message>
        <source>list-trainees: also write JSON to &lt;file&gt;.</source>
        <translation>list-trainees: zusätzlich JSON in &lt;file&gt; schreiben.</translation>
    </message>
    <message>
        <source>Usage: microsim-cli db migrate|backup FILE|restore FILE|export-csv FILE --instructor NAME|list-trainees|add-trainee NAME [--group G]|add-instructor NAME --password-stdin [--db FILE_OR_URL]</source>
        <translation>Aufruf: microsim-cli db migrate|backup DATEI|restore DATEI|export-csv DATEI --instructor NAME|list-trainees|add-trainee NAME [--group G]|add-instructor NAME --password-stdin [--db DATEI_ODER_URL]</translation>
    </message>
    <message>
        <source>%1: schema version %2</source>
        <translation>%1: Schemaversion %2</translation>
    </message>
    <message>
        <source>backed up %1 to %2</source>
        <translation>%1 nach %2 gesichert</translation>
    </message>
    <message>
        <source>restored %1 from %2 (schema version %3)</source>
        <translation>%1 aus %2 wiederhergestellt (Schemaversion %3)</translation>
    </message>
    <message>
        <source>wrote %1</source>
        <translation>%1 geschrieben</translation>
    </message>
    <message>
        <source>id</source>
        <translation>ID</translation>
    </message>
    <message>
        <source>role</source>
        <translation>Rolle</translation>
    </message>
    <message>
        <source>group</source>
        <translation>Gruppe</translation>
    </message>
    <message>
        <source>name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>added trainee %1 (id %2)</source>
        <translation>Trainee %1 hinzugefügt (ID %2)</translation>
    </message>
    <message>
        <source>added instructor %1 (id %2)</source>
        <translation>Ausbilder %1 hinzugefügt (ID %2)</translation>
    </message>
    <message>
        <source>tissue link %1 over-stretched (%2 %)</source>
        <translation>Gewebeverbindung %1 überdehnt (%2 %)</translation>
    </message>
    <message numerus="yes">
        <source>tissue tears: %n link(s) removed</source>
        <translation><numerusform>Gewebe reißt: %n Verbindung entfernt</numerusform><numerusform>Gewebe reißt: %n Verbindungen entfernt</numerusform></translation>
    </message>
    <message>
        <source>cannot open the rubric file</source>
        <translation>die Bewertungsdatei lässt sich nicht öffnen</translation>
    </message>
    <message>
        <source>wrong type</source>
        <translation>falscher Typ</translation>
    </message>
    <message>
        <source>missing field</source>
        <translation>fehlendes Feld</translation>
    </message>
    <message>
        <source>unknown metric</source>
        <translation>unbekannte Kennzahl</translation>
    </message>
    <message>
        <source>invalid value</source>
        <translation>ungültiger Wert</translation>
    </message>
    <message>
        <source>rubric</source>
        <translation>Bewertungsschema</translation>
    </message>
    <message>
        <source>version %1, pass mark %2</source>
        <translation>Version %1, Bestehensgrenze %2</translation>
    </message>
    <message>
        <source>recording</source>
        <translation>Aufzeichnung</translation>
    </message>
    <message numerus="yes">
        <source>%n frame(s)</source>
        <translation><numerusform>%n Bild</numerusform><numerusform>%n Bilder</numerusform></translation>
    </message>
    <message>
        <source>(unfinished: scored as far as it goes)</source>
        <translation>(unvollständig: bewertet, soweit vorhanden)</translation>
    </message>
    <message>
        <source>score</source>
        <translation>Punktzahl</translation>
    </message>
    <message>
        <source>passed</source>
        <translation>bestanden</translation>
    </message>
    <message>
        <source>not passed</source>
        <translation>nicht bestanden</translation>
    </message>
    <message>
        <source>never-event</source>
        <translation>Never-Event</translation>
    </message>
    <message>
        <source>metric</source>
        <translation>Kennzahl</translation>
    </message>
    <message>
        <source>value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>unit</source>
        <translation>Einheit</translation>
    </message>
    <message>
        <source>target</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <source>weight</source>
        <translation>Gewicht</translation>
    </message>
    <message>
        <source>points</source>
        <translation>Punkte</translation>
    </message>
    <message>
        <source>feedback</source>
        <translation>Rückmeldung</translation>
    </message>
    <message>
        <source>pierces</source>
        <translation>Einstiche</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>%1 s, end %2, %3 → %4, entry %5°, exit %6°, bite %7 mm, at %8°</source>
        <translation>%1 s, Ende %2, %3 → %4, Einstich %5°, Ausstich %6°, Stichabstand %7 mm, bei %8°</translation>
    </message>
    <message>
        <source>full thickness</source>
        <translation>durch die ganze Wand</translation>
    </message>
    <message>
        <source>back wall</source>
        <translation>Hinterwand</translation>
    </message>
    <message>
        <source>cannot store the attempt: %1</source>
        <translation>der Versuch lässt sich nicht speichern: %1</translation>
    </message>
    <message>
        <source>The recording &lt;file&gt; to score.</source>
        <translation>Die zu bewertende Aufzeichnung &lt;file&gt;.</translation>
    </message>
    <message>
        <source>The rubric &lt;file&gt; that grades it.</source>
        <translation>Das Bewertungsschema &lt;file&gt;, nach dem bewertet wird.</translation>
    </message>
    <message>
        <source>The scene &lt;file&gt; (default: the one the recording names).</source>
        <translation>Die Szene &lt;file&gt; (Vorgabe: die in der Aufzeichnung genannte).</translation>
    </message>
    <message>
        <source>Store the attempt in the history database &lt;file or URL&gt;.</source>
        <translation>Den Versuch in der Verlaufsdatenbank &lt;file or URL&gt; speichern.</translation>
    </message>
    <message>
        <source>The trainee the attempt belongs to (with --db; added when new).</source>
        <translation>Der Lernende, dem der Versuch gehört (mit --db; wird angelegt, wenn neu).</translation>
    </message>
    <message>
        <source>The lesson stored with the attempt (default: the rubric's id).</source>
        <translation>Die mit dem Versuch gespeicherte Lektion (Vorgabe: die Kennung des Bewertungsschemas).</translation>
    </message>
    <message>
        <source>The attempt's mode stored with --db: learn or test (default test).</source>
        <translation>Der mit --db gespeicherte Modus des Versuchs: learn oder test (Vorgabe test).</translation>
    </message>
    <message>
        <source>Write the score, metrics and pierces as JSON to &lt;file&gt;.</source>
        <translation>Punktzahl, Kennzahlen und Einstiche als JSON in &lt;file&gt; schreiben.</translation>
    </message>
    <message>
        <source>Usage: microsim-cli score --recording REC --rubric FILE [--scene FILE] [--db FILE --trainee NAME [--lesson ID] [--mode learn|test]] [--json OUT]</source>
        <translation>Aufruf: microsim-cli score --recording REC --rubric FILE [--scene FILE] [--db FILE --trainee NAME [--lesson ID] [--mode learn|test]] [--json OUT]</translation>
    </message>
    <message>
        <source>--recording REC and --rubric FILE are required</source>
        <translation>--recording REC und --rubric FILE sind erforderlich</translation>
    </message>
    <message>
        <source>--db and --trainee go together</source>
        <translation>--db und --trainee gehören zusammen</translation>
    </message>
    <message>
        <source>--mode is learn or test, not '%1'</source>
        <translation>--mode ist learn oder test, nicht '%1'</translation>
    </message>
    <message numerus="yes">
        <source>scoring its %n complete frame(s)</source>
        <translation><numerusform>bewerte ihr %n vollständiges Bild</numerusform><numerusform>bewerte ihre %n vollständigen Bilder</numerusform></translation>
    </message>
    <message>
        <source>the recording names no scene: give --scene FILE</source>
        <translation>die Aufzeichnung nennt keine Szene: --scene FILE angeben</translation>
    </message>
    <message>
        <source>stored as attempt %1</source>
        <translation>als Versuch %1 gespeichert</translation>
    </message>
    <message>
        <source>Write every accepted pose and channel value as a tracker stream to &lt;file&gt;.</source>
        <translation>Jede angenommene Pose und jeden Kanalwert als Trackerstrom in &lt;file&gt; schreiben.</translation>
    </message>
    <message>
        <source>Usage: microsim-cli track --igtl HOST:PORT [--duration S] [--json FILE] [--record FILE] [--once] [--max-speed MM_S]</source>
        <translation>Aufruf: microsim-cli track --igtl HOST:PORT [--duration S] [--json DATEI] [--record DATEI] [--once] [--max-speed MM_S]</translation>
    </message>
    <message>
        <source>the file could not be read or written</source>
        <translation>die Datei konnte nicht gelesen oder geschrieben werden</translation>
    </message>
    <message>
        <source>%1: [%2/%3] %4 (%5 s)</source>
        <translation>%1: [%2/%3] %4 (%5 s)</translation>
    </message>
    <message>
        <source>this build has no benchmarks (configure with -DMICROSIM_BUILD_BENCHMARKS=ON)</source>
        <translation>dieser Build enthält keine Benchmarks (mit -DMICROSIM_BUILD_BENCHMARKS=ON konfigurieren)</translation>
    </message>
    <message>
        <source>name one benchmark (see --list)</source>
        <translation>bitte genau einen Benchmark nennen (siehe --list)</translation>
    </message>
    <message>
        <source>unknown benchmark '%1' (see --list)</source>
        <translation>unbekannter Benchmark „%1“ (siehe --list)</translation>
    </message>
    <message>
        <source>'%1' has no curves to plot</source>
        <translation>„%1“ hat keine Kurven zum Zeichnen</translation>
    </message>
    <message>
        <source>cannot write the plot %1</source>
        <translation>das Diagramm %1 kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>cannot read %1</source>
        <translation>%1 kann nicht gelesen werden</translation>
    </message>
    <message>
        <source>%1 is not a JSON object: %2</source>
        <translation>%1 ist kein JSON-Objekt: %2</translation>
    </message>
    <message numerus="yes">
        <source>%1 was cut short (the recording stopped before its end); using its %n complete sample(s)</source>
        <translation><numerusform>%1 ist unvollständig (die Aufzeichnung endete vorzeitig); verwendet wird sein %n vollständiges Sample</numerusform><numerusform>%1 ist unvollständig (die Aufzeichnung endete vorzeitig); verwendet werden seine %n vollständigen Samples</numerusform></translation>
    </message>
    <message>
        <source>say pivot or register, and give --input FILE</source>
        <translation>pivot oder register angeben und --input DATEI nennen</translation>
    </message>
    <message>
        <source>warning: %1</source>
        <translation>Warnung: %1</translation>
    </message>
    <message>
        <source>the file or name the action takes</source>
        <translation>die Datei oder der Name, den die Aktion erwartet</translation>
    </message>
    <message>
        <source>name an action: %1</source>
        <translation>bitte eine Aktion nennen: %1</translation>
    </message>
    <message>
        <source>unknown action '%1' (known: %2)</source>
        <translation>unbekannte Aktion „%1“ (bekannt: %2)</translation>
    </message>
    <message>
        <source>%1 needs a file or a name after it</source>
        <translation>%1 braucht danach eine Datei oder einen Namen</translation>
    </message>
    <message>
        <source>add-instructor reads the password from stdin: give --password-stdin</source>
        <translation>add-instructor liest das Passwort von stdin: --password-stdin angeben</translation>
    </message>
    <message>
        <source>export-csv needs --instructor NAME (password on stdin)</source>
        <translation>export-csv braucht --instructor NAME (Passwort über stdin)</translation>
    </message>
    <message>
        <source>%1 exists already; it was left untouched. Choose another name for the backup, or move that file away first.</source>
        <translation>%1 existiert bereits und wurde nicht verändert. Wählen Sie einen anderen Namen für die Sicherung oder verschieben Sie diese Datei zuerst.</translation>
    </message>
    <message>
        <source>give the server as --igtl HOST:PORT</source>
        <translation>den Server als --igtl HOST:PORT angeben</translation>
    </message>
    <message>
        <source>--duration and --max-speed take positive numbers</source>
        <translation>--duration und --max-speed erwarten positive Zahlen</translation>
    </message>
    <message>
        <source>cannot write %1</source>
        <translation>%1 kann nicht geschrieben werden</translation>
    </message>
    <message>
        <source>could not connect to %1:%2: %3</source>
        <translation>keine Verbindung zu %1:%2: %3</translation>
    </message>
    <message>
        <source>the recording was made on the scene %1, which is not there, not beside the recording and not among the shipped scenes (looked at: %2); give --scene FILE</source>
        <translation>die Aufzeichnung wurde mit der Szene %1 gemacht, die weder dort noch neben der Aufzeichnung noch unter den mitgelieferten Szenen liegt (gesucht in: %2); --scene DATEI angeben</translation>
    </message>
    <message>
        <source>%1 has changed since the recording was made on it (%2): the replay may differ from the attempt</source>
        <translation>%1 wurde geändert, seit die Aufzeichnung damit gemacht wurde (%2): die Wiedergabe kann vom Versuch abweichen</translation>
    </message>
    <message>
        <source>The scene &lt;file&gt; to run (default with --input: the one the recording names).</source>
        <translation>Die auszuführende Szene &lt;file&gt; (Vorgabe mit --input: die, die die Aufzeichnung nennt).</translation>
    </message>
    <message>
        <source>Usage: microsim-cli run (--scene FILE [--input REC | --script NAME] | --input REC) [--record REC] [--frames N] [--json OUT]</source>
        <translation>Aufruf: microsim-cli run (--scene DATEI [--input AUFZ | --script NAME] | --input AUFZ) [--record AUFZ] [--frames N] [--json AUS]</translation>
    </message>
    <message>
        <source>give --scene FILE, or --input REC to replay it on the scene it was recorded on</source>
        <translation>--scene DATEI angeben, oder --input AUFZ, um sie auf der Szene wiederzugeben, mit der sie aufgezeichnet wurde</translation>
    </message>
    <message>
        <source>forceps closes on nothing: nothing lies between its jaws</source>
        <translation>Pinzette schließt ins Leere: zwischen ihren Branchen liegt nichts</translation>
    </message>
    <message>
        <source>scissors cut the thread, leaving a %1 mm end</source>
        <translation>die Schere schneidet den Faden und lässt ein Ende von %1 mm</translation>
    </message>
    <message>
        <source>scissors cut the thread</source>
        <translation>die Schere schneidet den Faden</translation>
    </message>
    <message>
        <source>the needle keeps %1 mm of thread, too short to tie</source>
        <translation>der Nadel bleiben %1 mm Faden, zu kurz zum Knoten</translation>
    </message>
    <message>
        <source>no knot</source>
        <translation>kein Knoten</translation>
    </message>
    <message>
        <source>a single throw</source>
        <translation>ein einfacher Wurf</translation>
    </message>
    <message>
        <source>a square knot</source>
        <translation>ein Kreuzknoten</translation>
    </message>
    <message>
        <source>a granny knot</source>
        <translation>ein Altweiberknoten</translation>
    </message>
    <message>
        <source>a surgeon's knot</source>
        <translation>ein chirurgischer Knoten</translation>
    </message>
    <message>
        <source>a slip knot</source>
        <translation>ein Slipknoten</translation>
    </message>
    <message>
        <source>an unknown knot</source>
        <translation>ein unbekannter Knoten</translation>
    </message>
    <message>
        <source>right-handed</source>
        <translation>rechtshändig</translation>
    </message>
    <message>
        <source>left-handed</source>
        <translation>linkshändig</translation>
    </message>
    <message numerus="yes">
        <source>throw %1 formed: %2, %n wrap(s); the knot reads %3</source>
        <translation><numerusform>Wurf %1 gebildet: %2, %n Windung; der Knoten ist %3</numerusform><numerusform>Wurf %1 gebildet: %2, %n Windungen; der Knoten ist %3</numerusform></translation>
    </message>
    <message numerus="yes">
        <source>%1 pulled tight: %n throw(s), tension %2 µN</source>
        <translation><numerusform>%1 festgezogen: %n Wurf, Spannung %2 µN</numerusform><numerusform>%1 festgezogen: %n Würfe, Spannung %2 µN</numerusform></translation>
    </message>
    <message>
        <source>the knot slips: it ran %1 mm along the thread under %2 µN</source>
        <translation>der Knoten rutscht: er lief %1 mm den Faden entlang bei %2 µN</translation>
    </message>
    <message numerus="yes">
        <source>the knot slips: %n throw(s) left, it reads %1</source>
        <translation><numerusform>der Knoten rutscht: %n Wurf bleibt, er ist %1</numerusform><numerusform>der Knoten rutscht: %n Würfe bleiben, er ist %1</numerusform></translation>
    </message>
    <message>
        <source>end product</source>
        <translation>Endergebnis</translation>
    </message>
    <message>
        <source>lapse index %1</source>
        <translation>Lapse-Index %1</translation>
    </message>
    <message>
        <source>error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>stitch</source>
        <translation>Naht</translation>
    </message>
    <message>
        <source>pierce</source>
        <translation>Einstich</translation>
    </message>
    <message>
        <source>at (°)</source>
        <translation>bei (°)</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>gemessen</translation>
    </message>
    <message>
        <source>limit</source>
        <translation>Grenze</translation>
    </message>
    <message>
        <source>the scene has no severed vessel</source>
        <translation>die Szene hat kein durchtrenntes Gefäß</translation>
    </message>
    <message>
        <source>no stitch joins the two ends</source>
        <translation>keine Naht verbindet die beiden Enden</translation>
    </message>
    <message>
        <source>a stitch names a face the tissue does not have</source>
        <translation>eine Naht nennt eine Fläche, die das Gewebe nicht hat</translation>
    </message>
    <message>
        <source>the pressurised wall did not settle</source>
        <translation>die Wand unter Druck kam nicht ins Gleichgewicht</translation>
    </message>
    <message>
        <source>the pressurised wall could not be solved</source>
        <translation>die Wand unter Druck ließ sich nicht berechnen</translation>
    </message>
    <message>
        <source>leak test</source>
        <translation>Dichtigkeitsprüfung</translation>
    </message>
    <message>
        <source>not done: %1</source>
        <translation>nicht durchgeführt: %1</translation>
    </message>
    <message>
        <source>%1 mmHg: largest gap %2 mm at %3°, limit %4 mm</source>
        <translation>%1 mmHg: größter Spalt %2 mm bei %3°, Grenze %4 mm</translation>
    </message>
    <message>
        <source>leaks</source>
        <translation>undicht</translation>
    </message>
    <message>
        <source>holds</source>
        <translation>dicht</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Micro-anastomosis training simulator</source>
        <translation>Trainingssimulator für Mikroanastomosen</translation>
    </message>
    <message>
        <source>Write a PNG of each main screen to &lt;dir&gt;, then quit.</source>
        <translation>Von jedem Hauptbildschirm ein PNG nach &lt;dir&gt; schreiben und beenden.</translation>
    </message>
    <message>
        <source>dir</source>
        <translation>Verzeichnis</translation>
    </message>
    <message>
        <source>Use the SQLite history file &lt;file&gt; instead of the default.</source>
        <translation>Die SQLite-Verlaufsdatei &lt;file&gt; statt der voreingestellten verwenden.</translation>
    </message>
    <message>
        <source>file</source>
        <translation>Datei</translation>
    </message>
    <message>
        <source>cannot create %1</source>
        <translation>%1 kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>Start as usual, quit once the main window is drawn; exit 1 if it was not, or a lesson or the history could not be read.</source>
        <translation>Wie gewohnt starten und beenden, sobald das Hauptfenster gezeichnet ist; Exit-Code 1, wenn es nicht gezeichnet wurde oder eine Lektion oder der Verlauf nicht gelesen werden konnte.</translation>
    </message>
    <message>
        <source>the main window was not drawn within %1 s</source>
        <translation>das Hauptfenster wurde nicht innerhalb von %1 s gezeichnet</translation>
    </message>
    <message>
        <source>no lesson files in %1</source>
        <translation>keine Lektionsdateien in %1</translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n lesson file(s) in %2 could be read</source>
        <translation><numerusform>%1 von %n Lektionsdatei in %2 lesbar</numerusform><numerusform>%1 von %n Lektionsdateien in %2 lesbar</numerusform></translation>
    </message>
    <message numerus="yes">
        <source>microsim started: %n lesson(s) from %1, history %2</source>
        <translation><numerusform>microsim gestartet: %n Lektion aus %1, Verlauf %2</numerusform><numerusform>microsim gestartet: %n Lektionen aus %1, Verlauf %2</numerusform></translation>
    </message>
</context>
<context>
    <name>microsim::gui::AddPersonDialog</name>
    <message>
        <source>Add a trainee</source>
        <translation>Auszubildende(n) hinzufügen</translation>
    </message>
    <message>
        <source>Add an instructor</source>
        <translation>Ausbilder(in) hinzufügen</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Hinzufügen</translation>
    </message>
</context>
<context>
    <name>microsim::gui::AttemptDetailView</name>
    <message>
        <source>Metric</source>
        <translation>Messgröße</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Toleranz</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>Gewicht</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>Punkte</translation>
    </message>
    <message>
        <source>Feedback</source>
        <translation>Rückmeldung</translation>
    </message>
    <message>
        <source>Pierce</source>
        <translation>Stich</translation>
    </message>
    <message>
        <source>A note for this attempt…</source>
        <translation>Eine Notiz zu diesem Versuch …</translation>
    </message>
    <message>
        <source>Add note</source>
        <translation>Notiz hinzufügen</translation>
    </message>
    <message>
        <source>Metrics</source>
        <translation>Messgrößen</translation>
    </message>
    <message>
        <source>Pierces</source>
        <translation>Stiche</translation>
    </message>
    <message>
        <source>Annotations</source>
        <translation>Notizen</translation>
    </message>
    <message>
        <source>Replay in 3D</source>
        <translation>In 3D abspielen</translation>
    </message>
    <message>
        <source>Choose an attempt in a trainee's history.</source>
        <translation>Wählen Sie einen Versuch im Verlauf eines Trainees.</translation>
    </message>
    <message>
        <source>%1 — %2, %3, %4</source>
        <translation>%1 – %2, %3, %4</translation>
    </message>
    <message>
        <source>Score %1 of 100 (%2); rubric %3 version %4</source>
        <translation>%1 von 100 Punkten (%2); Bewertungsschema %3, Version %4</translation>
    </message>
    <message>
        <source>passed</source>
        <translation>bestanden</translation>
    </message>
    <message>
        <source>not passed</source>
        <translation>nicht bestanden</translation>
    </message>
    <message>
        <source>No recording stored.</source>
        <translation>Keine Aufzeichnung gespeichert.</translation>
    </message>
    <message>
        <source>The lesson's scene is not installed.</source>
        <translation>Die Szene der Lektion ist nicht installiert.</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>no</source>
        <translation>nein</translation>
    </message>
    <message>
        <source>%1, %2:
%3</source>
        <translation>%1, %2:
%3</translation>
    </message>
    <message numerus="yes">
        <source>Replay finished: %n frame(s).</source>
        <translation><numerusform>Wiedergabe beendet: %n Bild.</numerusform><numerusform>Wiedergabe beendet: %n Bilder.</numerusform></translation>
    </message>
    <message>
        <source>The stored recording is damaged.</source>
        <translation>Die gespeicherte Aufzeichnung ist beschädigt.</translation>
    </message>
    <message>
        <source>The lesson's scene could not be loaded.</source>
        <translation>Die Szene der Lektion konnte nicht geladen werden.</translation>
    </message>
    <message numerus="yes">
        <source>Replaying %n frame(s)…</source>
        <translation><numerusform>%n Bild wird abgespielt …</numerusform><numerusform>%n Bilder werden abgespielt …</numerusform></translation>
    </message>
    <message>
        <source>Paused.</source>
        <translation>Angehalten.</translation>
    </message>
    <message>
        <source>End product</source>
        <translation>Endergebnis</translation>
    </message>
</context>
<context>
    <name>microsim::gui::AttemptPage</name>
    <message>
        <source>Finish attempt</source>
        <translation>Versuch beenden</translation>
    </message>
    <message>
        <source>Abandon</source>
        <translation>Aufgeben</translation>
    </message>
    <message>
        <source>The rubric %1 cannot be read (field %2, line %3).</source>
        <translation>Das Bewertungsschema %1 ist nicht lesbar (Feld %2, Zeile %3).</translation>
    </message>
    <message>
        <source>The scene %1 cannot be loaded (field %2, line %3).</source>
        <translation>Die Szene %1 kann nicht geladen werden (Feld %2, Zeile %3).</translation>
    </message>
    <message>
        <source>Learn mode: each step is ticked off as you do it.</source>
        <translation>Lernmodus: jeder Schritt wird abgehakt, sobald Sie ihn ausgeführt haben.</translation>
    </message>
    <message>
        <source>Learn mode: follow the marks.</source>
        <translation>Lernmodus: folgen Sie den Markierungen.</translation>
    </message>
    <message>
        <source>Test mode: graded, no hints.</source>
        <translation>Prüfungsmodus: bewertet, ohne Hilfen.</translation>
    </message>
    <message>
        <source>This attempt is not stored (no history).</source>
        <translation>Dieser Versuch wird nicht gespeichert (kein Verlauf).</translation>
    </message>
    <message>
        <source>Replaying a recording…</source>
        <translation>Eine Aufzeichnung wird abgespielt …</translation>
    </message>
    <message>
        <source>Every step is done: finish the attempt when you are ready.</source>
        <translation>Alle Schritte sind erledigt: beenden Sie den Versuch, wenn Sie so weit sind.</translation>
    </message>
    <message>
        <source>Scoring…</source>
        <translation>Bewertung …</translation>
    </message>
    <message>
        <source>The recording %1 could not be replayed for scoring.</source>
        <translation>Die Aufzeichnung %1 konnte zur Bewertung nicht abgespielt werden.</translation>
    </message>
    <message>
        <source>The score could not be stored (%1).</source>
        <translation>Die Bewertung konnte nicht gespeichert werden (%1).</translation>
    </message>
    <message>
        <source>Abandon the attempt?</source>
        <translation>Versuch aufgeben?</translation>
    </message>
    <message>
        <source>The attempt ends here without a score. It stays in your history as abandoned.</source>
        <translation>Der Versuch endet hier ohne Bewertung. Er bleibt als aufgegeben in Ihrem Verlauf.</translation>
    </message>
    <message>
        <source>Keep practising</source>
        <translation>Weiter üben</translation>
    </message>
    <message>
        <source>The tissue solver %1 chosen in the settings is not known; choose another.</source>
        <translation>Der in den Einstellungen gewählte Gewebelöser %1 ist unbekannt; wählen Sie einen anderen.</translation>
    </message>
    <message>
        <source>This attempt is not stored: the history refused it (%1).</source>
        <translation>Dieser Versuch wird nicht gespeichert: der Verlauf hat ihn abgelehnt (%1).</translation>
    </message>
    <message>
        <source>The history could not mark the attempt abandoned (%1).</source>
        <translation>Der Verlauf konnte den Versuch nicht als aufgegeben markieren (%1).</translation>
    </message>
    <message>
        <source>The left forceps closed on nothing: nothing lay between its jaws.</source>
        <translation>Die linke Pinzette hat ins Leere gegriffen: zwischen ihren Branchen lag nichts.</translation>
    </message>
    <message>
        <source>The right forceps closed on nothing: nothing lay between its jaws.</source>
        <translation>Die rechte Pinzette hat ins Leere gegriffen: zwischen ihren Branchen lag nichts.</translation>
    </message>
    <message>
        <source>The scissors cut the thread: the cut end is %1 long.</source>
        <translation>Die Schere hat den Faden geschnitten: Das Fadenende ist %1 lang.</translation>
    </message>
    <message>
        <source>The scissors cut the thread: no stitch holds it on either side of the cut.</source>
        <translation>Die Schere hat den Faden geschnitten: Auf keiner Seite des Schnitts hält ihn ein Stich.</translation>
    </message>
    <message>
        <source>Too short to tie: the needle keeps only %1 of thread.</source>
        <translation>Zu kurz zum Knoten: Der Nadel bleiben nur %1 Faden.</translation>
    </message>
</context>
<context>
    <name>microsim::gui::CalibrationSession</name>
    <message>
        <source>Cannot read %1.</source>
        <translation>%1 kann nicht gelesen werden.</translation>
    </message>
    <message>
        <source>%1 is neither a recording nor a tracker stream.</source>
        <translation>%1 ist weder eine Aufzeichnung noch ein Trackerstrom.</translation>
    </message>
    <message>
        <source>%1 is damaged.</source>
        <translation>%1 ist beschädigt.</translation>
    </message>
    <message>
        <source>Save setup profile</source>
        <translation>Einrichtungsprofil speichern</translation>
    </message>
    <message>
        <source>The database is not open.</source>
        <translation>Die Datenbank ist nicht geöffnet.</translation>
    </message>
    <message>
        <source>Profile name:</source>
        <translation>Profilname:</translation>
    </message>
    <message>
        <source>Calibrated by:</source>
        <translation>Kalibriert von:</translation>
    </message>
    <message>
        <source>The profile could not be stored: %1</source>
        <translation>Das Profil konnte nicht gespeichert werden: %1</translation>
    </message>
    <message>
        <source>&amp;Calibration</source>
        <translation>&amp;Kalibrierung</translation>
    </message>
    <message>
        <source>Calibration</source>
        <translation>Kalibrierung</translation>
    </message>
    <message>
        <source>Connect a tracker or open a tracker recording first.</source>
        <translation>Verbinden Sie zuerst einen Tracker oder öffnen Sie eine Trackeraufzeichnung.</translation>
    </message>
    <message>
        <source>Connect to OpenIGTLink…</source>
        <translation>Mit OpenIGTLink verbinden…</translation>
    </message>
    <message>
        <source>Connect to OpenIGTLink</source>
        <translation>Mit OpenIGTLink verbinden</translation>
    </message>
    <message>
        <source>Server (host:port):</source>
        <translation>Server (Host:Port):</translation>
    </message>
    <message>
        <source>Give the server as host:port.</source>
        <translation>Geben Sie den Server als Host:Port an.</translation>
    </message>
    <message>
        <source>Play a tracker recording…</source>
        <translation>Trackeraufzeichnung abspielen…</translation>
    </message>
    <message>
        <source>Play a tracker recording</source>
        <translation>Trackeraufzeichnung abspielen</translation>
    </message>
    <message>
        <source>Recordings (*.json *.msrec)</source>
        <translation>Aufzeichnungen (*.json *.msrec)</translation>
    </message>
    <message>
        <source>Setup profile…</source>
        <translation>Einrichtungsprofil…</translation>
    </message>
    <message>
        <source>Save setup profile…</source>
        <translation>Einrichtungsprofil speichern…</translation>
    </message>
    <message>
        <source>Pivot calibration…</source>
        <translation>Pivot-Kalibrierung…</translation>
    </message>
    <message>
        <source>Registration…</source>
        <translation>Registrierung…</translation>
    </message>
    <message>
        <source>Forceps closure…</source>
        <translation>Pinzettenschluss…</translation>
    </message>
    <message>
        <source>Left hand</source>
        <translation>Linke Hand</translation>
    </message>
    <message>
        <source>Right hand</source>
        <translation>Rechte Hand</translation>
    </message>
    <message>
        <source>Forceps closure</source>
        <translation>Pinzettenschluss</translation>
    </message>
    <message>
        <source>Hand:</source>
        <translation>Hand:</translation>
    </message>
    <message>
        <source>Motion scaling…</source>
        <translation>Bewegungsskalierung…</translation>
    </message>
    <message>
        <source>Latency…</source>
        <translation>Latenz…</translation>
    </message>
    <message>
        <source>Live view of the tools</source>
        <translation>Live-Ansicht der Instrumente</translation>
    </message>
    <message>
        <source>Calibrated tools</source>
        <translation>Kalibrierte Instrumente</translation>
    </message>
    <message>
        <source>Use a 3D mouse (spacenavd)</source>
        <translation>3D-Maus verwenden (spacenavd)</translation>
    </message>
    <message>
        <source>3D mouse</source>
        <translation>3D-Maus</translation>
    </message>
    <message>
        <source>3D mouse connected: push or turn the cap to move the active forceps; the left button closes the jaws, the right one switches the hand.</source>
        <translation>3D-Maus verbunden: die Kappe schieben oder drehen, um die aktive Pinzette zu bewegen; die linke Taste schließt die Branchen, die rechte wechselt die Hand.</translation>
    </message>
    <message>
        <source>Use a game controller</source>
        <translation>Gamecontroller verwenden</translation>
    </message>
    <message>
        <source>Game controller</source>
        <translation>Gamecontroller</translation>
    </message>
    <message>
        <source>%1 connected: sticks move the active forceps, the triggers close the jaws, the shoulder buttons choose the hand.</source>
        <translation>%1 verbunden: die Sticks bewegen die aktive Pinzette, die Trigger schließen die Branchen, die Schultertasten wählen die Hand.</translation>
    </message>
</context>
<context>
    <name>microsim::gui::ClosureDialog</name>
    <message>
        <source>Forceps closure</source>
        <translation>Pinzettenschluss</translation>
    </message>
    <message>
        <source>Open the jaws fully, then squeeze them shut a few times.</source>
        <translation>Öffnen Sie die Branchen ganz und drücken Sie sie dann einige Male zu.</translation>
    </message>
    <message>
        <source>Start again</source>
        <translation>Neu beginnen</translation>
    </message>
    <message>
        <source>Channel:</source>
        <translation>Kanal:</translation>
    </message>
    <message>
        <source>No reading yet.</source>
        <translation>Noch kein Messwert.</translation>
    </message>
    <message numerus="yes">
        <source>Open %1 · closed %2 (%n reading(s))</source>
        <translation><numerusform>Offen %1 · geschlossen %2 (%n Messwert)</numerusform><numerusform>Offen %1 · geschlossen %2 (%n Messwerte)</numerusform></translation>
    </message>
</context>
<context>
    <name>microsim::gui::EndProductPanel</name>
    <message>
        <source>&lt;b&gt;Opened vessel&lt;/b&gt;: cut along its axis and laid flat; 0° faces the microscope. Dots are passages, blue lines the stitches' thread, numbered marks the errors.</source>
        <translation>&lt;b&gt;Eröffnetes Gefäß&lt;/b&gt;: entlang der Achse aufgeschnitten und flach ausgebreitet; 0° zeigt zum Mikroskop. Punkte sind Stiche durch die Wand, blaue Linien der Faden der Nähte, nummerierte Zeichen die Fehler.</translation>
    </message>
    <message>
        <source>#</source>
        <translation>Nr.</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>Where</source>
        <translation>Wo</translation>
    </message>
    <message>
        <source>Measured</source>
        <translation>Gemessen</translation>
    </message>
    <message>
        <source>The end product was not judged: this attempt was scored before its errors were kept.</source>
        <translation>Das Endergebnis wurde nicht beurteilt: Dieser Versuch wurde bewertet, bevor seine Fehler gespeichert wurden.</translation>
    </message>
    <message>
        <source>No end-product errors.</source>
        <translation>Keine Fehler im Endergebnis.</translation>
    </message>
    <message>
        <source>stitch %1</source>
        <translation>Naht %1</translation>
    </message>
    <message>
        <source>pierce %1</source>
        <translation>Stich %1</translation>
    </message>
    <message>
        <source>at %1°</source>
        <comment>an angle round the vessel</comment>
        <translation>bei %1°</translation>
    </message>
    <message>
        <source>not located</source>
        <translation>ohne Ort</translation>
    </message>
    <message>
        <source>%1 wall thicknesses</source>
        <translation>%1 Wanddicken</translation>
    </message>
    <message>
        <source>bites %1 apart</source>
        <translation>Stiche %1 auseinander</translation>
    </message>
    <message>
        <source>gap %1 off the mean</source>
        <translation>Abstand %1 neben dem Mittel</translation>
    </message>
    <message>
        <source>%1 (limit %2)</source>
        <translation>%1 (Grenze %2)</translation>
    </message>
    <message>
        <source>End-product errors (Anastomosis Lapse Index): %1</source>
        <translation>Fehler im Endergebnis (Anastomosis Lapse Index): %1</translation>
    </message>
    <message>
        <source>links torn: %1</source>
        <translation>gerissene Verbindungen: %1</translation>
    </message>
    <message>
        <source>bites squeezed by %1</source>
        <translation>Stiche um %1 gestaucht</translation>
    </message>
    <message>
        <source>%1 into the lumen</source>
        <translation>%1 ins Lumen hinein</translation>
    </message>
    <message>
        <source>edges past each other, %1 out of line</source>
        <translation>Ränder übereinander, %1 versetzt</translation>
    </message>
</context>
<context>
    <name>microsim::gui::FeedbackText</name>
    <message>
        <source>Take the same bite on both ends.</source>
        <translation>Stechen Sie an beiden Enden gleich weit vom Rand.</translation>
    </message>
    <message>
        <source>Pass through the whole wall, not only part of it.</source>
        <translation>Stechen Sie durch die ganze Wand, nicht nur durch einen Teil.</translation>
    </message>
    <message>
        <source>Enter closer to the cut edge.</source>
        <translation>Stechen Sie näher am Schnittrand ein.</translation>
    </message>
    <message>
        <source>Enter further from the cut edge: the stitch may tear out.</source>
        <translation>Stechen Sie weiter vom Schnittrand ein: die Naht kann ausreißen.</translation>
    </message>
    <message>
        <source>Enter the wall more perpendicularly.</source>
        <translation>Stechen Sie senkrechter in die Wand ein.</translation>
    </message>
    <message>
        <source>Follow the needle's curve so it leaves the wall perpendicularly.</source>
        <translation>Folgen Sie der Krümmung der Nadel, damit sie senkrecht aus der Wand austritt.</translation>
    </message>
    <message>
        <source>Re-grasp less: plan each grip.</source>
        <translation>Weniger nachgreifen: planen Sie jeden Griff.</translation>
    </message>
    <message>
        <source>Fewer pauses: keep the movement going.</source>
        <translation>Weniger Pausen: bleiben Sie in Bewegung.</translation>
    </message>
    <message>
        <source>Move more smoothly.</source>
        <translation>Bewegen Sie sich gleichmäßiger.</translation>
    </message>
    <message>
        <source>Shorter, more direct instrument paths.</source>
        <translation>Kürzere, direktere Instrumentenwege.</translation>
    </message>
    <message>
        <source>The back wall was caught: this closes the vessel.</source>
        <translation>Die Hinterwand wurde mitgefasst: das verschließt das Gefäß.</translation>
    </message>
    <message>
        <source>The suture broke: pull more gently.</source>
        <translation>Der Faden ist gerissen: ziehen Sie sanfter.</translation>
    </message>
    <message>
        <source>The tissue was torn or over-stretched.</source>
        <translation>Das Gewebe wurde gerissen oder überdehnt.</translation>
    </message>
    <message>
        <source>The needle did not pass through the wall.</source>
        <translation>Die Nadel ist nicht durch die Wand gegangen.</translation>
    </message>
    <message>
        <source>The stitch was not completed through both ends.</source>
        <translation>Die Naht wurde nicht durch beide Enden geführt.</translation>
    </message>
    <message>
        <source>Too few stitches.</source>
        <translation>Zu wenige Nähte.</translation>
    </message>
    <message>
        <source>More stitches than needed.</source>
        <translation>Mehr Nähte als nötig.</translation>
    </message>
    <message>
        <source>Counts only once part of the task is done.</source>
        <translation>Zählt erst, wenn ein Teil der Aufgabe erledigt ist.</translation>
    </message>
    <message>
        <source>Work faster.</source>
        <translation>Arbeiten Sie zügiger.</translation>
    </message>
    <message>
        <source>Handle the tissue more gently: it was over-stretched.</source>
        <translation>Behandeln Sie das Gewebe sanfter: es wurde überdehnt.</translation>
    </message>
    <message>
        <source>Space the first three stitches 120° apart.</source>
        <translation>Setzen Sie die ersten drei Nähte im Abstand von 120°.</translation>
    </message>
    <message>
        <source>%1: not measured in this attempt.</source>
        <translation>%1: in diesem Versuch nicht gemessen.</translation>
    </message>
    <message>
        <source>%1 is too high.</source>
        <translation>%1 ist zu hoch.</translation>
    </message>
    <message>
        <source>%1 is too low.</source>
        <translation>%1 ist zu niedrig.</translation>
    </message>
    <message>
        <source>Pass each wall once: every extra passage injures it.</source>
        <translation>Jede Wand nur einmal durchstechen: jeder weitere Durchstich verletzt sie.</translation>
    </message>
    <message>
        <source>Turn the needle along its curve instead of pushing it.</source>
        <translation>Die Nadel entlang ihrer Krümmung drehen, statt sie zu schieben.</translation>
    </message>
    <message>
        <source>The needle was dragged sideways through the tissue, not turned along its curve.</source>
        <translation>Die Nadel wurde seitlich durch das Gewebe gezogen statt entlang ihrer Krümmung gedreht.</translation>
    </message>
    <message>
        <source>%1: not applicable to this input; not counted.</source>
        <translation>%1: für diese Eingabe nicht anwendbar; nicht gewertet.</translation>
    </message>
    <message>
        <source>Cut both tails of every knot with the microscissors (T).</source>
        <translation>Schneiden Sie beide Fadenenden jedes Knotens mit der Mikroschere (T) ab.</translation>
    </message>
    <message>
        <source>Cut the tails shorter: about 1 mm from the knot.</source>
        <translation>Schneiden Sie die Fadenenden kürzer: etwa 1 mm vom Knoten.</translation>
    </message>
    <message>
        <source>Leave longer tails, about 1 mm: a tail cut at the knot lets it untie.</source>
        <translation>Lassen Sie längere Fadenenden, etwa 1 mm: ein am Knoten abgeschnittenes Ende lässt ihn aufgehen.</translation>
    </message>
    <message>
        <source>The finished anastomosis has errors: see the list of lapses.</source>
        <translation>Die fertige Anastomose hat Fehler: siehe die Liste der Mängel.</translation>
    </message>
    <message>
        <source>Tie a square or surgeon's knot: a double throw, then a single throw the other way.</source>
        <translation>Knüpfen Sie einen Kreuzknoten oder chirurgischen Knoten: einen Doppelwurf, dann einen einfachen Wurf in der Gegenrichtung.</translation>
    </message>
    <message>
        <source>Tie every stitch: wrap the thread round the forceps, grasp the tail, pull it through.</source>
        <translation>Knüpfen Sie jede Naht: den Faden um die Pinzette wickeln, das kurze Ende fassen, durchziehen.</translation>
    </message>
    <message>
        <source>Lay at least two throws, the second the other way round.</source>
        <translation>Legen Sie mindestens zwei Würfe, den zweiten in der Gegenrichtung.</translation>
    </message>
    <message>
        <source>A knot slipped: the stitch would open. Alternate the throws and snug each one down.</source>
        <translation>Ein Knoten ist gerutscht: die Naht würde aufgehen. Wechseln Sie die Wurfrichtung und ziehen Sie jeden Wurf an.</translation>
    </message>
    <message>
        <source>The suture line leaks under pressure: close the widest gap with another stitch.</source>
        <translation>Die Nahtreihe ist unter Druck undicht: schließen Sie die größte Lücke mit einer weiteren Naht.</translation>
    </message>
</context>
<context>
    <name>microsim::gui::LatencyDialog</name>
    <message>
        <source>Latency</source>
        <translation>Latenz</translation>
    </message>
    <message>
        <source>Hold the tool and the reference together and move them briskly in every direction for about ten seconds.</source>
        <translation>Halten Sie Instrument und Referenz zusammen und bewegen Sie sie etwa zehn Sekunden lang zügig in alle Richtungen.</translation>
    </message>
    <message>
        <source>Record</source>
        <translation>Aufnehmen</translation>
    </message>
    <message>
        <source>Tracked device:</source>
        <translation>Getracktes Gerät:</translation>
    </message>
    <message>
        <source>Reference device:</source>
        <translation>Referenzgerät:</translation>
    </message>
    <message>
        <source>Stop and estimate</source>
        <translation>Anhalten und schätzen</translation>
    </message>
    <message>
        <source>Recording…</source>
        <translation>Aufnahme läuft…</translation>
    </message>
    <message>
        <source>Latency %1 ms (correlation %2)</source>
        <translation>Latenz %1 ms (Korrelation %2)</translation>
    </message>
    <message>
        <source>Too short: record longer.</source>
        <translation>Zu kurz: länger aufnehmen.</translation>
    </message>
    <message>
        <source>The devices sent invalid samples.</source>
        <translation>Die Geräte haben ungültige Werte gesendet.</translation>
    </message>
    <message>
        <source>No motion: move the tool.</source>
        <translation>Keine Bewegung: bewegen Sie das Instrument.</translation>
    </message>
    <message>
        <source>The motions do not match (correlation %1): move them together.</source>
        <translation>Die Bewegungen passen nicht zusammen (Korrelation %1): bewegen Sie beide gemeinsam.</translation>
    </message>
</context>
<context>
    <name>microsim::gui::LessonListPage</name>
    <message>
        <source>Lesson</source>
        <translation>Lektion</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Stand</translation>
    </message>
    <message>
        <source>Learn (guided)</source>
        <translation>Lernen (geführt)</translation>
    </message>
    <message>
        <source>Test (graded)</source>
        <translation>Prüfung (bewertet)</translation>
    </message>
    <message>
        <source>Sign out</source>
        <translation>Abmelden</translation>
    </message>
    <message>
        <source>&lt;h2&gt;Lessons for %1&lt;/h2&gt;</source>
        <translation>&lt;h2&gt;Lektionen für %1&lt;/h2&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;Goals&lt;/b&gt;&lt;ul&gt;</source>
        <translation>&lt;b&gt;Ziele&lt;/b&gt;&lt;ul&gt;</translation>
    </message>
    <message>
        <source>My progress</source>
        <translation>Mein Fortschritt</translation>
    </message>
    <message>
        <source>Your scores over your attempts, each attempt's feedback and your instructors' notes</source>
        <translation>Ihre Punktzahlen über Ihre Versuche, die Rückmeldung zu jedem Versuch und die Notizen Ihrer Ausbilder</translation>
    </message>
    <message>
        <source>The history could not be read: %1</source>
        <translation>Der Verlauf konnte nicht gelesen werden: %1</translation>
    </message>
</context>
<context>
    <name>microsim::gui::LessonStatusText</name>
    <message>
        <source>not started</source>
        <translation>nicht begonnen</translation>
    </message>
    <message>
        <source>practised</source>
        <translation>geübt</translation>
    </message>
    <message>
        <source>passed</source>
        <translation>bestanden</translation>
    </message>
    <message>
        <source>proficient</source>
        <translation>sicher beherrscht</translation>
    </message>
</context>
<context>
    <name>microsim::gui::LiveToolView</name>
    <message>
        <source>top (x–y)</source>
        <translation>oben (x–y)</translation>
    </message>
    <message>
        <source>side (x–z)</source>
        <translation>seitlich (x–z)</translation>
    </message>
</context>
<context>
    <name>microsim::gui::MainWindow</name>
    <message>
        <source>microsim — micro-anastomosis trainer</source>
        <translation>microsim — Mikroanastomose-Trainer</translation>
    </message>
    <message>
        <source>History: %1 (schema %2)</source>
        <translation>Verlauf: %1 (Schema %2)</translation>
    </message>
    <message>
        <source>History unavailable: cannot create the folder for %1</source>
        <translation>Verlauf nicht verfügbar: der Ordner für %1 kann nicht angelegt werden</translation>
    </message>
    <message>
        <source>History unavailable: cannot open %1</source>
        <translation>Verlauf nicht verfügbar: %1 kann nicht geöffnet werden</translation>
    </message>
    <message>
        <source>History unavailable: %1 is not a microsim database or is damaged; it was left untouched</source>
        <translation>Verlauf nicht verfügbar: %1 ist keine microsim-Datenbank oder beschädigt; die Datei wurde nicht verändert</translation>
    </message>
    <message>
        <source>History unavailable: %1 is locked by another program</source>
        <translation>Verlauf nicht verfügbar: %1 ist von einem anderen Programm gesperrt</translation>
    </message>
    <message>
        <source>History unavailable: %1 was written by a newer microsim</source>
        <translation>Verlauf nicht verfügbar: %1 wurde von einer neueren microsim-Version geschrieben</translation>
    </message>
    <message>
        <source>History unavailable: updating %1 failed; it was left as it was</source>
        <translation>Verlauf nicht verfügbar: die Aktualisierung von %1 ist fehlgeschlagen; die Datei blieb unverändert</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Settings</source>
        <translation>&amp;Einstellungen</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>&amp;About microsim</source>
        <translation>Ü&amp;ber microsim</translation>
    </message>
    <message>
        <source>The language changes at the next start.</source>
        <translation>Die Sprache wechselt beim nächsten Start.</translation>
    </message>
    <message>
        <source>About microsim</source>
        <translation>Über microsim</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;microsim %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Practise and assessment of microvascular anastomosis under a virtual operating microscope.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;microsim %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Übung und Bewertung mikrovaskulärer Anastomosen unter einem virtuellen Operationsmikroskop.&lt;/p&gt;</translation>
    </message>
    <message numerus="yes">
        <source>%n lesson file(s) could not be read; the first: %1 (%2)</source>
        <translation><numerusform>%n Lektionsdatei konnte nicht gelesen werden; die erste: %1 (%2)</numerusform><numerusform>%n Lektionsdateien konnten nicht gelesen werden; die erste: %1 (%2)</numerusform></translation>
    </message>
    <message>
        <source>Instructor: %1</source>
        <translation>Ausbilder(in): %1</translation>
    </message>
    <message>
        <source>Trainee: %1</source>
        <translation>Auszubildende(r): %1</translation>
    </message>
    <message>
        <source>History unavailable: %1 is read-only; it was left untouched</source>
        <translation>Verlauf nicht verfügbar: %1 ist schreibgeschützt; sie wurde nicht verändert</translation>
    </message>
    <message>
        <source>&amp;Replay a recording into this attempt…</source>
        <translation>Aufzeichnung in diesen Versuch &amp;abspielen …</translation>
    </message>
    <message>
        <source>&amp;Preferences…</source>
        <translation>&amp;Einstellungen …</translation>
    </message>
    <message>
        <source>The lesson cannot start</source>
        <translation>Die Lektion kann nicht beginnen</translation>
    </message>
    <message>
        <source>Start a lesson first; the recording is then replayed into it.</source>
        <translation>Beginnen Sie zuerst eine Lektion; die Aufzeichnung wird dann darin abgespielt.</translation>
    </message>
    <message>
        <source>Replay a recording</source>
        <translation>Aufzeichnung abspielen</translation>
    </message>
    <message>
        <source>Recordings (*.msrec)</source>
        <translation>Aufzeichnungen (*.msrec)</translation>
    </message>
    <message>
        <source>%1 is not a readable recording.</source>
        <translation>%1 ist keine lesbare Aufzeichnung.</translation>
    </message>
    <message>
        <source>Settings saved; the solver applies from the next attempt.</source>
        <translation>Einstellungen gespeichert; der Löser gilt ab dem nächsten Versuch.</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;Microscope view (reset)</source>
        <translation>&amp;Mikroskopansicht (zurücksetzen)</translation>
    </message>
    <message>
        <source>&amp;Top view</source>
        <translation>Ansicht von &amp;oben</translation>
    </message>
    <message>
        <source>&amp;Oblique view</source>
        <translation>&amp;Schräge Ansicht</translation>
    </message>
    <message>
        <source>&amp;Side view</source>
        <translation>Ansicht von der S&amp;eite</translation>
    </message>
    <message>
        <source>&amp;Keys and mouse</source>
        <translation>&amp;Tasten und Maus</translation>
    </message>
    <message>
        <source>&amp;People</source>
        <translation>&amp;Personen</translation>
    </message>
    <message>
        <source>Add a &amp;trainee…</source>
        <translation>&amp;Auszubildende(n) hinzufügen …</translation>
    </message>
    <message>
        <source>Add an &amp;instructor…</source>
        <translation>Ausb&amp;ilder(in) hinzufügen …</translation>
    </message>
    <message>
        <source>Trainee %1 added.</source>
        <translation>Auszubildende(r) %1 hinzugefügt.</translation>
    </message>
    <message>
        <source>Instructor %1 added.</source>
        <translation>Ausbilder(in) %1 hinzugefügt.</translation>
    </message>
    <message>
        <source>&amp;Depth of field</source>
        <translation>&amp;Schärfentiefe</translation>
    </message>
    <message>
        <source>Blur what lies above or below the focal plane, as a microscope does</source>
        <translation>Was über oder unter der Schärfeebene liegt, unscharf zeigen, wie ein Mikroskop es tut</translation>
    </message>
</context>
<context>
    <name>microsim::gui::MetricVocabulary</name>
    <message>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>Path length</source>
        <translation>Weglänge</translation>
    </message>
    <message>
        <source>Path length, left hand</source>
        <translation>Weglänge, linke Hand</translation>
    </message>
    <message>
        <source>Path length, right hand</source>
        <translation>Weglänge, rechte Hand</translation>
    </message>
    <message>
        <source>Movements</source>
        <translation>Bewegungen</translation>
    </message>
    <message>
        <source>Smoothness</source>
        <translation>Laufruhe</translation>
    </message>
    <message>
        <source>Idle time</source>
        <translation>Leerlaufzeit</translation>
    </message>
    <message>
        <source>Re-grasps</source>
        <translation>Nachgriffe</translation>
    </message>
    <message>
        <source>Suture breaks</source>
        <translation>Fadenrisse</translation>
    </message>
    <message>
        <source>Largest tissue stretch</source>
        <translation>Größte Gewebedehnung</translation>
    </message>
    <message>
        <source>Tissue damage</source>
        <translation>Gewebeschäden</translation>
    </message>
    <message>
        <source>Wall passages</source>
        <translation>Wanddurchstiche</translation>
    </message>
    <message>
        <source>Needle off its arc</source>
        <translation>Nadel außerhalb ihres Bogens</translation>
    </message>
    <message>
        <source>Entry angle</source>
        <translation>Einstichwinkel</translation>
    </message>
    <message>
        <source>Exit angle</source>
        <translation>Ausstichwinkel</translation>
    </message>
    <message>
        <source>Bite</source>
        <translation>Stichabstand</translation>
    </message>
    <message>
        <source>Bite in wall thicknesses</source>
        <translation>Stichabstand in Wanddicken</translation>
    </message>
    <message>
        <source>Full-thickness passages</source>
        <translation>Durchstiche durch die ganze Wand</translation>
    </message>
    <message>
        <source>Back-wall catches</source>
        <translation>Hinterwand gefasst</translation>
    </message>
    <message>
        <source>Stitches</source>
        <translation>Nähte</translation>
    </message>
    <message>
        <source>Bite asymmetry</source>
        <translation>Asymmetrie der Stiche</translation>
    </message>
    <message>
        <source>Stitch spacing</source>
        <translation>Nahtabstand</translation>
    </message>
    <message>
        <source>Triangulation error</source>
        <translation>Triangulationsfehler</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Position am Umfang</translation>
    </message>
    <message>
        <source>Full thickness</source>
        <translation>Ganze Wand</translation>
    </message>
    <message>
        <source>Back wall</source>
        <translation>Hinterwand</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <comment>a label and its unit</comment>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Anastomosis lapse index</source>
        <translation>Anastomosis Lapse Index (Fehlerzahl)</translation>
    </message>
    <message>
        <source>Oblique stitches</source>
        <translation>Schräge Nähte</translation>
    </message>
    <message>
        <source>Partial-thickness bites</source>
        <translation>Stiche nicht durch die ganze Wand</translation>
    </message>
    <message>
        <source>Wide bites</source>
        <translation>Zu weite Stiche</translation>
    </message>
    <message>
        <source>Unequally spaced stitches</source>
        <translation>Ungleich verteilte Nähte</translation>
    </message>
    <message>
        <source>Knots tied</source>
        <translation>Geknüpfte Knoten</translation>
    </message>
    <message>
        <source>Secure knots</source>
        <translation>Sichere Knoten</translation>
    </message>
    <message>
        <source>Knots slipped</source>
        <translation>Gerutschte Knoten</translation>
    </message>
    <message>
        <source>Throws per knot</source>
        <translation>Würfe pro Knoten</translation>
    </message>
    <message>
        <source>Tails cut</source>
        <translation>Abgeschnittene Fadenenden</translation>
    </message>
    <message>
        <source>Cut-end length</source>
        <translation>Länge der Fadenenden</translation>
    </message>
    <message>
        <source>Leaks under pressure</source>
        <translation>Undicht unter Druck</translation>
    </message>
    <message>
        <source>Largest gap under pressure</source>
        <translation>Größte Lücke unter Druck</translation>
    </message>
</context>
<context>
    <name>microsim::gui::MotionScalingDialog</name>
    <message>
        <source>Motion scaling</source>
        <translation>Bewegungsskalierung</translation>
    </message>
    <message>
        <source> mm per mm</source>
        <translation> mm pro mm</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Hand motion per scene motion:</source>
        <translation>Handbewegung pro Szenenbewegung:</translation>
    </message>
    <message>
        <source>Fixed scene point (x, y, z):</source>
        <translation>Fester Szenenpunkt (x, y, z):</translation>
    </message>
</context>
<context>
    <name>microsim::gui::MyProgressPage</name>
    <message>
        <source>&lt;h2&gt;My progress&lt;/h2&gt;</source>
        <translation>&lt;h2&gt;Mein Fortschritt&lt;/h2&gt;</translation>
    </message>
    <message>
        <source>Back to the lessons</source>
        <translation>Zurück zu den Lektionen</translation>
    </message>
    <message>
        <source>Lesson:</source>
        <translation>Lektion:</translation>
    </message>
    <message>
        <source>Scores</source>
        <translation>Punktzahlen</translation>
    </message>
    <message>
        <source>Attempt</source>
        <translation>Versuch</translation>
    </message>
    <message>
        <source>Reading your history…</source>
        <translation>Ihr Verlauf wird gelesen …</translation>
    </message>
    <message>
        <source>Your history could not be read (%1).</source>
        <translation>Ihr Verlauf konnte nicht gelesen werden (%1).</translation>
    </message>
    <message numerus="yes">
        <source>%n of these attempts carry an instructor's note: choose one to read it.</source>
        <translation><numerusform>%n dieser Versuche trägt eine Notiz eines Ausbilders: wählen Sie ihn, um sie zu lesen.</numerusform><numerusform>%n dieser Versuche tragen eine Notiz eines Ausbilders: wählen Sie einen, um sie zu lesen.</numerusform></translation>
    </message>
</context>
<context>
    <name>microsim::gui::NewPersonForm</name>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keine</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>Gruppe</translation>
    </message>
    <message numerus="yes">
        <source>at least %n characters</source>
        <translation><numerusform>mindestens %n Zeichen</numerusform><numerusform>mindestens %n Zeichen</numerusform></translation>
    </message>
    <message>
        <source>Password</source>
        <translation>Passwort</translation>
    </message>
    <message>
        <source>Password again</source>
        <translation>Passwort wiederholen</translation>
    </message>
    <message>
        <source>Type a name first.</source>
        <translation>Geben Sie zuerst einen Namen ein.</translation>
    </message>
    <message numerus="yes">
        <source>The password needs at least %n characters.</source>
        <translation><numerusform>Das Passwort braucht mindestens %n Zeichen.</numerusform><numerusform>Das Passwort braucht mindestens %n Zeichen.</numerusform></translation>
    </message>
    <message>
        <source>The two passwords differ; type them again.</source>
        <translation>Die beiden Passwörter unterscheiden sich; geben Sie sie erneut ein.</translation>
    </message>
    <message>
        <source>A person called %1 already exists.</source>
        <translation>Eine Person namens %1 gibt es bereits.</translation>
    </message>
    <message>
        <source>An instructor has been set up meanwhile; sign in as them.</source>
        <translation>Inzwischen wurde ein(e) Ausbilder(in) eingerichtet; melden Sie sich als diese(r) an.</translation>
    </message>
    <message>
        <source>%1 could not be added (%2).</source>
        <translation>%1 konnte nicht hinzugefügt werden (%2).</translation>
    </message>
</context>
<context>
    <name>microsim::gui::OpenedVesselImage</name>
    <message>
        <source>%1 (%2)</source>
        <comment>an error not located: its kind, its number in the error list</comment>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Not located: %1</source>
        <translation>Ohne Ort: %1</translation>
    </message>
    <message>
        <source>end 1</source>
        <translation>Ende 1</translation>
    </message>
    <message>
        <source>end 2</source>
        <translation>Ende 2</translation>
    </message>
    <message>
        <source>%1°</source>
        <comment>an angle round the vessel</comment>
        <translation>%1°</translation>
    </message>
    <message>
        <source>front wall</source>
        <translation>Vorderwand</translation>
    </message>
    <message>
        <source>back wall</source>
        <translation>Hinterwand</translation>
    </message>
    <message>
        <source>S%1</source>
        <comment>stitch number on the opened vessel</comment>
        <translation>N%1</translation>
    </message>
</context>
<context>
    <name>microsim::gui::PivotWizard</name>
    <message>
        <source>Pivot the tool</source>
        <translation>Instrument schwenken</translation>
    </message>
    <message>
        <source>Hold the tip still in the divot and tilt the tool in every direction (at least %1°). Poses are collected automatically.</source>
        <translation>Halten Sie die Spitze ruhig in der Mulde und neigen Sie das Instrument in alle Richtungen (mindestens %1°). Die Posen werden automatisch gesammelt.</translation>
    </message>
    <message>
        <source>Spread %1° — enough</source>
        <translation>Streuung %1° — ausreichend</translation>
    </message>
    <message>
        <source>Spread %1° — tilt further</source>
        <translation>Streuung %1° — weiter neigen</translation>
    </message>
    <message>
        <source>Tip offset</source>
        <translation>Spitzenversatz</translation>
    </message>
    <message>
        <source>Collect again</source>
        <translation>Erneut sammeln</translation>
    </message>
    <message>
        <source>Tip (tool frame): %1, %2, %3 mm
Pivot (tracker frame): %4, %5, %6 mm
RMS error %7 mm, largest %8 mm
%9 poses, spread %10°</source>
        <translation>Spitze (Instrumentsystem): %1, %2, %3 mm
Drehpunkt (Trackersystem): %4, %5, %6 mm
RMS-Fehler %7 mm, größter %8 mm
%9 Posen, Streuung %10°</translation>
    </message>
    <message>
        <source>Pivot calibration</source>
        <translation>Pivot-Kalibrierung</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Instrument</translation>
    </message>
    <message>
        <source>Choose the tracked device of the tool to calibrate.</source>
        <translation>Wählen Sie das getrackte Gerät des zu kalibrierenden Instruments.</translation>
    </message>
    <message>
        <source>Left hand</source>
        <translation>Linke Hand</translation>
    </message>
    <message>
        <source>Right hand</source>
        <translation>Rechte Hand</translation>
    </message>
    <message>
        <source>Device:</source>
        <translation>Gerät:</translation>
    </message>
    <message>
        <source>Hand:</source>
        <translation>Hand:</translation>
    </message>
    <message>
        <source>Accepted: the error is within the threshold.</source>
        <translation>Angenommen: der Fehler liegt innerhalb der Schwelle.</translation>
    </message>
    <message>
        <source>Too few poses: collect again.</source>
        <translation>Zu wenige Posen: erneut sammeln.</translation>
    </message>
    <message>
        <source>The tracker sent invalid poses: collect again.</source>
        <translation>Der Tracker hat ungültige Posen gesendet: erneut sammeln.</translation>
    </message>
    <message>
        <source>The tool was not tilted enough: collect again.</source>
        <translation>Das Instrument wurde nicht genug geneigt: erneut sammeln.</translation>
    </message>
    <message>
        <source>The error is above the threshold (the tip slipped or the tool bent): collect again.</source>
        <translation>Der Fehler liegt über der Schwelle (die Spitze ist verrutscht oder das Instrument verbogen): erneut sammeln.</translation>
    </message>
</context>
<context>
    <name>microsim::gui::ProfileChooserDialog</name>
    <message>
        <source>Setup profile</source>
        <translation>Einrichtungsprofil</translation>
    </message>
    <message>
        <source>Use</source>
        <translation>Verwenden</translation>
    </message>
    <message>
        <source>Import…</source>
        <translation>Importieren…</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>Exportieren…</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Löschen</translation>
    </message>
    <message>
        <source>Import setup profile</source>
        <translation>Einrichtungsprofil importieren</translation>
    </message>
    <message>
        <source>JSON (*.json)</source>
        <translation>JSON (*.json)</translation>
    </message>
    <message>
        <source>Export setup profile</source>
        <translation>Einrichtungsprofil exportieren</translation>
    </message>
    <message>
        <source>%1 — %2 by %3</source>
        <translation>%1 — %2 von %3</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>unbekannt</translation>
    </message>
    <message>
        <source>FRE %1 mm</source>
        <translation>FRE %1 mm</translation>
    </message>
    <message>
        <source>TRE %1 mm</source>
        <translation>TRE %1 mm</translation>
    </message>
    <message>
        <source>Cannot read %1.</source>
        <translation>%1 kann nicht gelesen werden.</translation>
    </message>
    <message>
        <source>The profile could not be stored: %1</source>
        <translation>Das Profil konnte nicht gespeichert werden: %1</translation>
    </message>
    <message>
        <source>The file is not a JSON document.</source>
        <translation>Die Datei ist kein JSON-Dokument.</translation>
    </message>
    <message>
        <source>The file is not a microsim setup profile (%1).</source>
        <translation>Die Datei ist kein microsim-Einrichtungsprofil (%1).</translation>
    </message>
    <message>
        <source>The field "%1" is missing.</source>
        <translation>Das Feld „%1“ fehlt.</translation>
    </message>
    <message>
        <source>The field "%1" has the wrong type.</source>
        <translation>Das Feld „%1“ hat den falschen Typ.</translation>
    </message>
    <message>
        <source>The field "%1" has a value that is not allowed.</source>
        <translation>Das Feld „%1“ hat einen unzulässigen Wert.</translation>
    </message>
    <message>
        <source>The profile could not be read: %1</source>
        <translation>Das Profil konnte nicht gelesen werden: %1</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
</context>
<context>
    <name>microsim::gui::RegistrationWizard</name>
    <message>
        <source>Points</source>
        <translation>Punkte</translation>
    </message>
    <message>
        <source>Type each point's scene position, hold the tip on it and press Touch. Three fiducials at least; check points measure the error elsewhere.</source>
        <translation>Geben Sie die Szenenposition jedes Punktes ein, halten Sie die Spitze darauf und drücken Sie „Antippen“. Mindestens drei Passermarken; Kontrollpunkte messen den Fehler an anderer Stelle.</translation>
    </message>
    <message>
        <source>Add point</source>
        <translation>Punkt hinzufügen</translation>
    </message>
    <message>
        <source>Touch</source>
        <translation>Antippen</translation>
    </message>
    <message>
        <source>Registration</source>
        <translation>Registrierung</translation>
    </message>
    <message>
        <source>FRE (fit): %1 mm RMS, %2 mm largest</source>
        <translation>FRE (Anpassung): %1 mm RMS, größter %2 mm</translation>
    </message>
    <message numerus="yes">
        <source>TRE (%n check point(s)): %1 mm RMS, %2 mm largest</source>
        <translation><numerusform>TRE (%n Kontrollpunkt): %1 mm RMS, größter %2 mm</numerusform><numerusform>TRE (%n Kontrollpunkte): %1 mm RMS, größter %2 mm</numerusform></translation>
    </message>
    <message>
        <source>No check points: the TRE is unknown.</source>
        <translation>Keine Kontrollpunkte: der TRE ist unbekannt.</translation>
    </message>
    <message>
        <source>Role</source>
        <translation>Rolle</translation>
    </message>
    <message>
        <source>Scene x</source>
        <translation>Szene x</translation>
    </message>
    <message>
        <source>Scene y</source>
        <translation>Szene y</translation>
    </message>
    <message>
        <source>Scene z</source>
        <translation>Szene z</translation>
    </message>
    <message>
        <source>Tracker x</source>
        <translation>Tracker x</translation>
    </message>
    <message>
        <source>Tracker y</source>
        <translation>Tracker y</translation>
    </message>
    <message>
        <source>Tracker z</source>
        <translation>Tracker z</translation>
    </message>
    <message>
        <source>Fiducial</source>
        <translation>Passermarke</translation>
    </message>
    <message>
        <source>Check point</source>
        <translation>Kontrollpunkt</translation>
    </message>
    <message>
        <source>Registered.</source>
        <translation>Registriert.</translation>
    </message>
    <message>
        <source>Touch at least three fiducials.</source>
        <translation>Tippen Sie mindestens drei Passermarken an.</translation>
    </message>
    <message>
        <source>Every point needs both positions.</source>
        <translation>Jeder Punkt braucht beide Positionen.</translation>
    </message>
    <message>
        <source>A position is not a number.</source>
        <translation>Eine Position ist keine Zahl.</translation>
    </message>
    <message>
        <source>The fiducials lie on one line: spread them out.</source>
        <translation>Die Passermarken liegen auf einer Linie: verteilen Sie sie.</translation>
    </message>
</context>
<context>
    <name>microsim::gui::ReplayControls</name>
    <message>
        <source>To the start (Home)</source>
        <translation>Zum Anfang (Pos1)</translation>
    </message>
    <message>
        <source>One frame back (Left)</source>
        <translation>Ein Bild zurück (Links)</translation>
    </message>
    <message>
        <source>Play (Space)</source>
        <translation>Abspielen (Leertaste)</translation>
    </message>
    <message>
        <source>One frame on (Right)</source>
        <translation>Ein Bild weiter (Rechts)</translation>
    </message>
    <message>
        <source>To the end (End)</source>
        <translation>Zum Ende (Ende)</translation>
    </message>
    <message>
        <source>Replay position</source>
        <translation>Position der Wiedergabe</translation>
    </message>
    <message>
        <source>Playback speed</source>
        <translation>Wiedergabegeschwindigkeit</translation>
    </message>
    <message>
        <source>%1×</source>
        <translation>%1×</translation>
    </message>
    <message>
        <source>Stepping from the start: %p%</source>
        <translation>Neu gerechnet vom Anfang: %p %</translation>
    </message>
    <message>
        <source>%1 / %2 s</source>
        <translation>%1 / %2 s</translation>
    </message>
    <message>
        <source>Pause (Space)</source>
        <translation>Anhalten (Leertaste)</translation>
    </message>
</context>
<context>
    <name>microsim::gui::ReplayTimeline</name>
    <message>
        <source>Pierces</source>
        <translation>Durchstiche</translation>
    </message>
    <message>
        <source>Grasps and releases</source>
        <translation>Greifen und Loslassen</translation>
    </message>
    <message>
        <source>Tissue: over-stretch, tears, cuts</source>
        <translation>Gewebe: Überdehnung, Risse, Schnitte</translation>
    </message>
    <message>
        <source>Errors</source>
        <translation>Fehler</translation>
    </message>
    <message>
        <source>Pierce %1: the needle enters the wall</source>
        <translation>Durchstich %1: die Nadel tritt in die Wand ein</translation>
    </message>
    <message>
        <source>Pierce %1: the needle leaves the wall</source>
        <translation>Durchstich %1: die Nadel tritt aus der Wand aus</translation>
    </message>
    <message>
        <source>Grasp</source>
        <translation>Greifen</translation>
    </message>
    <message>
        <source>Release</source>
        <translation>Loslassen</translation>
    </message>
    <message>
        <source>Tissue over-stretched</source>
        <translation>Gewebe überdehnt</translation>
    </message>
    <message>
        <source>Tissue torn</source>
        <translation>Gewebe gerissen</translation>
    </message>
    <message>
        <source>Cut</source>
        <translation>Schnitt</translation>
    </message>
    <message>
        <source>Knot</source>
        <translation>Knoten</translation>
    </message>
    <message>
        <source>The forceps closed on nothing</source>
        <translation>Die Pinzette schloss sich ins Leere</translation>
    </message>
    <message>
        <source>The suture broke</source>
        <translation>Der Faden ist gerissen</translation>
    </message>
    <message>
        <source>Pierce %1: the suture slid out</source>
        <translation>Durchstich %1: der Faden ist herausgerutscht</translation>
    </message>
    <message>
        <source>Pierce %1: the needle left it before the thread</source>
        <translation>Durchstich %1: die Nadel verließ ihn vor dem Faden</translation>
    </message>
    <message>
        <source>%1 (left hand), %2 s</source>
        <translation>%1 (linke Hand), %2 s</translation>
    </message>
    <message>
        <source>%1 (right hand), %2 s</source>
        <translation>%1 (rechte Hand), %2 s</translation>
    </message>
    <message>
        <source>%1, %2 s</source>
        <translation>%1, %2 s</translation>
    </message>
    <message>
        <source>Knots and thread cuts</source>
        <translation>Knoten und Fadenschnitte</translation>
    </message>
    <message>
        <source>The scissors cut the thread</source>
        <translation>Die Schere schneidet den Faden</translation>
    </message>
    <message>
        <source>The needle was left too little thread to tie</source>
        <translation>Der Nadel blieb zu wenig Faden zum Knoten</translation>
    </message>
    <message>
        <source>The knot slipped</source>
        <translation>Der Knoten ist gerutscht</translation>
    </message>
</context>
<context>
    <name>microsim::gui::ResultsPage</name>
    <message>
        <source>Metric</source>
        <translation>Kennzahl</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Wert</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>Punkte</translation>
    </message>
    <message>
        <source>Advice</source>
        <translation>Hinweis</translation>
    </message>
    <message>
        <source>Retry</source>
        <translation>Noch einmal</translation>
    </message>
    <message>
        <source>Back to the lessons</source>
        <translation>Zurück zu den Lektionen</translation>
    </message>
    <message>
        <source>&lt;b&gt;Pierce angles&lt;/b&gt; (0° = perpendicular; red entry, blue exit)</source>
        <translation>&lt;b&gt;Einstichwinkel&lt;/b&gt; (0° = senkrecht; rot Einstich, blau Ausstich)</translation>
    </message>
    <message>
        <source>Test</source>
        <translation>Prüfung</translation>
    </message>
    <message>
        <source>Learn</source>
        <translation>Lernen</translation>
    </message>
    <message>
        <source>&lt;h2&gt;%1 — %2&lt;/h2&gt;</source>
        <translation>&lt;h2&gt;%1 — %2&lt;/h2&gt;</translation>
    </message>
    <message>
        <source>&lt;span style='font-size:28pt'&gt;–&lt;/span&gt;</source>
        <translation>&lt;span style='font-size:28pt'&gt;–&lt;/span&gt;</translation>
    </message>
    <message>
        <source>Not scored</source>
        <translation>Nicht bewertet</translation>
    </message>
    <message>
        <source>&lt;span style='font-size:28pt'&gt;&lt;b&gt;%1&lt;/b&gt; / 100&lt;/span&gt;</source>
        <translation>&lt;span style='font-size:28pt'&gt;&lt;b&gt;%1&lt;/b&gt; / 100&lt;/span&gt;</translation>
    </message>
    <message>
        <source>&lt;span style='color:#1b7f3a; font-size:16pt'&gt;Passed&lt;/span&gt;</source>
        <translation>&lt;span style='color:#1b7f3a; font-size:16pt'&gt;Bestanden&lt;/span&gt;</translation>
    </message>
    <message>
        <source>&lt;span style='color:#b00020; font-size:16pt'&gt;Not passed yet&lt;/span&gt;</source>
        <translation>&lt;span style='color:#b00020; font-size:16pt'&gt;Noch nicht bestanden&lt;/span&gt;</translation>
    </message>
    <message>
        <source>Scored from an incomplete recording.</source>
        <translation>Aus einer unvollständigen Aufzeichnung bewertet.</translation>
    </message>
    <message>
        <source>%1 (target %2)</source>
        <translation>%1 (Ziel %2)</translation>
    </message>
    <message>
        <source>Good.</source>
        <translation>Gut.</translation>
    </message>
</context>
<context>
    <name>microsim::gui::ReviewCharts</name>
    <message>
        <source>Score over attempts</source>
        <translation>Punkte über die Versuche</translation>
    </message>
    <message>
        <source>Attempt</source>
        <translation>Versuch</translation>
    </message>
    <message>
        <source>Score</source>
        <translation>Punkte</translation>
    </message>
    <message>
        <source>Pass mark</source>
        <translation>Bestehensgrenze</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>Ziel</translation>
    </message>
</context>
<context>
    <name>microsim::gui::ReviewPage</name>
    <message>
        <source>Export CSV…</source>
        <translation>CSV exportieren …</translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation>Aktualisieren</translation>
    </message>
    <message>
        <source>Sign out</source>
        <translation>Abmelden</translation>
    </message>
    <message>
        <source>Group:</source>
        <translation>Gruppe:</translation>
    </message>
    <message>
        <source>Best score (attempts). ✓ passed, ★ proficient: the pass mark on two consecutive Test attempts. Double-click a cell for the history.</source>
        <translation>Beste Punktzahl (Versuche). ✓ bestanden, ★ sicher beherrscht: die Bestehensgrenze in zwei aufeinanderfolgenden Prüfungsversuchen. Doppelklick auf eine Zelle zeigt den Verlauf.</translation>
    </message>
    <message>
        <source>PDF report…</source>
        <translation>PDF-Bericht …</translation>
    </message>
    <message>
        <source>Trainee:</source>
        <translation>Trainee:</translation>
    </message>
    <message>
        <source>Lesson:</source>
        <translation>Lektion:</translation>
    </message>
    <message>
        <source>Overview</source>
        <translation>Übersicht</translation>
    </message>
    <message>
        <source>History</source>
        <translation>Verlauf</translation>
    </message>
    <message>
        <source>Attempt</source>
        <translation>Versuch</translation>
    </message>
    <message>
        <source>The history could not be read.</source>
        <translation>Der Verlauf konnte nicht gelesen werden.</translation>
    </message>
    <message>
        <source>Instructor: %1</source>
        <translation>Ausbilder: %1</translation>
    </message>
    <message>
        <source>Trainee: %1</source>
        <translation>Trainee: %1</translation>
    </message>
    <message>
        <source>All groups</source>
        <translation>Alle Gruppen</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Trainee</source>
        <translation>Trainee</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>Gruppe</translation>
    </message>
    <message>
        <source>That attempt could not be read.</source>
        <translation>Dieser Versuch konnte nicht gelesen werden.</translation>
    </message>
    <message>
        <source>Only instructors can add notes.</source>
        <translation>Nur Ausbilder können Notizen hinzufügen.</translation>
    </message>
    <message>
        <source>The note could not be stored.</source>
        <translation>Die Notiz konnte nicht gespeichert werden.</translation>
    </message>
    <message>
        <source>Note added.</source>
        <translation>Notiz hinzugefügt.</translation>
    </message>
    <message>
        <source>Export attempts as CSV</source>
        <translation>Versuche als CSV exportieren</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>CSV-Dateien (*.csv)</translation>
    </message>
    <message>
        <source>Exported the attempts to %1.</source>
        <translation>Die Versuche wurden nach %1 exportiert.</translation>
    </message>
    <message>
        <source>Choose a trainee first.</source>
        <translation>Wählen Sie zuerst einen Trainee.</translation>
    </message>
    <message>
        <source>Save the report as PDF</source>
        <translation>Bericht als PDF speichern</translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation>PDF-Dateien (*.pdf)</translation>
    </message>
    <message>
        <source>Saved the report to %1.</source>
        <translation>Der Bericht wurde unter %1 gespeichert.</translation>
    </message>
    <message numerus="yes">
        <source>%n attempt(s): %1 finished, %2 abandoned</source>
        <translation><numerusform>%n Versuch: %1 beendet, %2 aufgegeben</numerusform><numerusform>%n Versuche: %1 beendet, %2 aufgegeben</numerusform></translation>
    </message>
</context>
<context>
    <name>microsim::gui::ReviewReport</name>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>%1 kann nicht geschrieben werden: %2</translation>
    </message>
    <message>
        <source>You may not export these attempts.</source>
        <translation>Sie dürfen diese Versuche nicht exportieren.</translation>
    </message>
    <message>
        <source>The export failed: %1</source>
        <translation>Der Export ist fehlgeschlagen: %1</translation>
    </message>
    <message>
        <source>Training report: %1</source>
        <translation>Trainingsbericht: %1</translation>
    </message>
    <message>
        <source>Cannot write %1.</source>
        <translation>%1 kann nicht geschrieben werden.</translation>
    </message>
    <message>
        <source>Group: %1</source>
        <translation>Gruppe: %1</translation>
    </message>
    <message>
        <source>Printed %1</source>
        <translation>Gedruckt am %1</translation>
    </message>
    <message>
        <source>Attempts</source>
        <translation>Versuche</translation>
    </message>
    <message>
        <source>#</source>
        <translation>Nr.</translation>
    </message>
    <message>
        <source>Lesson</source>
        <translation>Lektion</translation>
    </message>
    <message>
        <source>Started</source>
        <translation>Begonnen</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Modus</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Score</source>
        <translation>Punkte</translation>
    </message>
    <message>
        <source>Passed</source>
        <translation>Bestanden</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>no</source>
        <translation>nein</translation>
    </message>
    <message>
        <source>No attempts yet.</source>
        <translation>Noch keine Versuche.</translation>
    </message>
    <message>
        <source>End product</source>
        <translation>Endergebnis</translation>
    </message>
    <message>
        <source>Each vessel cut along its axis and laid flat: 0° faces the microscope, the back wall is shaded.</source>
        <translation>Jedes Gefäß entlang der Achse aufgeschnitten und flach ausgebreitet: 0° zeigt zum Mikroskop, die Hinterwand ist dunkler.</translation>
    </message>
    <message>
        <source>Attempt %1: %2, %3</source>
        <translation>Versuch %1: %2, %3</translation>
    </message>
</context>
<context>
    <name>microsim::gui::ReviewText</name>
    <message>
        <source>Nothing of the task was done, so time and handling were not scored.</source>
        <translation>Von der Aufgabe wurde nichts erledigt; Zeit und Handhabung wurden daher nicht bewertet.</translation>
    </message>
    <message>
        <source>Took longer than the target time.</source>
        <translation>Länger als die Zielzeit gebraucht.</translation>
    </message>
    <message>
        <source>The instruments travelled further than needed.</source>
        <translation>Die Instrumente haben einen längeren Weg als nötig zurückgelegt.</translation>
    </message>
    <message>
        <source>Movements were jerky; aim for smooth, continuous motion.</source>
        <translation>Die Bewegungen waren ruckartig; auf ruhige, fließende Bewegungen achten.</translation>
    </message>
    <message>
        <source>Long pauses with both hands still.</source>
        <translation>Lange Pausen mit beiden Händen in Ruhe.</translation>
    </message>
    <message>
        <source>The tissue was stretched too far.</source>
        <translation>Das Gewebe wurde zu stark gedehnt.</translation>
    </message>
    <message>
        <source>Too many re-grasps.</source>
        <translation>Zu viele Nachgriffe.</translation>
    </message>
    <message>
        <source>The wall was not passed with the needle.</source>
        <translation>Die Wand wurde nicht mit der Nadel durchstochen.</translation>
    </message>
    <message>
        <source>The needle entered too obliquely; enter perpendicular to the wall.</source>
        <translation>Die Nadel ist zu schräg eingestochen; senkrecht zur Wand einstechen.</translation>
    </message>
    <message>
        <source>The needle came out too obliquely; follow its curve.</source>
        <translation>Die Nadel ist zu schräg ausgetreten; ihrer Krümmung folgen.</translation>
    </message>
    <message>
        <source>Bites too far from the edge.</source>
        <translation>Stiche zu weit vom Rand entfernt.</translation>
    </message>
    <message>
        <source>Bites too close to the edge.</source>
        <translation>Stiche zu nah am Rand.</translation>
    </message>
    <message>
        <source>Some passages did not go through the whole wall.</source>
        <translation>Einige Durchstiche gingen nicht durch die ganze Wand.</translation>
    </message>
    <message>
        <source>The two bites of a stitch differ in length.</source>
        <translation>Die beiden Stiche einer Naht sind unterschiedlich lang.</translation>
    </message>
    <message>
        <source>Not all stitches were completed.</source>
        <translation>Nicht alle Nähte wurden fertiggestellt.</translation>
    </message>
    <message>
        <source>Too few stitches.</source>
        <translation>Zu wenige Nähte.</translation>
    </message>
    <message>
        <source>More stitches than needed.</source>
        <translation>Mehr Nähte als nötig.</translation>
    </message>
    <message>
        <source>The first stitches are not spaced 120° apart.</source>
        <translation>Die ersten Nähte liegen nicht 120° auseinander.</translation>
    </message>
    <message>
        <source>The back wall was caught: the lumen would be closed.</source>
        <translation>Die Hinterwand wurde gefasst: das Lumen wäre verschlossen.</translation>
    </message>
    <message>
        <source>The suture broke.</source>
        <translation>Der Faden ist gerissen.</translation>
    </message>
    <message>
        <source>The tissue was torn or over-stretched.</source>
        <translation>Das Gewebe wurde gerissen oder überdehnt.</translation>
    </message>
    <message>
        <source>%1: not measured in this attempt.</source>
        <translation>%1: in diesem Versuch nicht gemessen.</translation>
    </message>
    <message>
        <source>%1 too high.</source>
        <translation>%1 zu hoch.</translation>
    </message>
    <message>
        <source>%1 too low.</source>
        <translation>%1 zu niedrig.</translation>
    </message>
    <message>
        <source>Test</source>
        <translation>Prüfung</translation>
    </message>
    <message>
        <source>Learn</source>
        <translation>Lernen</translation>
    </message>
    <message>
        <source>In progress</source>
        <translation>Läuft</translation>
    </message>
    <message>
        <source>Finished</source>
        <translation>Beendet</translation>
    </message>
    <message>
        <source>Interrupted</source>
        <translation>Unterbrochen</translation>
    </message>
    <message>
        <source>Abandoned</source>
        <translation>Aufgegeben</translation>
    </message>
    <message>
        <source>The wall was passed more often than needed.</source>
        <translation>Die Wand wurde öfter als nötig durchstochen.</translation>
    </message>
    <message>
        <source>The needle was pushed rather than turned along its curve.</source>
        <translation>Die Nadel wurde geschoben statt entlang ihrer Krümmung gedreht.</translation>
    </message>
    <message>
        <source>The needle was dragged sideways through the tissue.</source>
        <translation>Die Nadel wurde seitlich durch das Gewebe gezogen.</translation>
    </message>
    <message>
        <source>%1: not applicable to this input; not counted.</source>
        <translation>%1: für diese Eingabe nicht anwendbar; nicht gewertet.</translation>
    </message>
    <message>
        <source>Not every stitch was tied.</source>
        <translation>Nicht jede Naht wurde geknüpft.</translation>
    </message>
    <message>
        <source>Knots were not square or surgeon's knots.</source>
        <translation>Die Knoten waren keine Kreuz- oder chirurgischen Knoten.</translation>
    </message>
    <message>
        <source>Knots had too few throws.</source>
        <translation>Die Knoten hatten zu wenige Würfe.</translation>
    </message>
    <message>
        <source>Not every tail was cut.</source>
        <translation>Nicht jedes Fadenende wurde abgeschnitten.</translation>
    </message>
    <message>
        <source>Tails were left too long.</source>
        <translation>Die Fadenenden blieben zu lang.</translation>
    </message>
    <message>
        <source>Tails were cut too short.</source>
        <translation>Die Fadenenden wurden zu kurz abgeschnitten.</translation>
    </message>
    <message>
        <source>The finished anastomosis has lapses.</source>
        <translation>Die fertige Anastomose hat Mängel.</translation>
    </message>
    <message>
        <source>A knot slipped: the stitch would open.</source>
        <translation>Ein Knoten ist gerutscht: die Naht würde aufgehen.</translation>
    </message>
    <message>
        <source>The suture line leaked under pressure.</source>
        <translation>Die Nahtreihe war unter Druck undicht.</translation>
    </message>
</context>
<context>
    <name>microsim::gui::SignInPage</name>
    <message>
        <source>&lt;h2&gt;Who is practising?&lt;/h2&gt;</source>
        <translation>&lt;h2&gt;Wer übt?&lt;/h2&gt;</translation>
    </message>
    <message>
        <source>Trainee</source>
        <translation>Auszubildende(r)</translation>
    </message>
    <message>
        <source>Sign in</source>
        <translation>Anmelden</translation>
    </message>
    <message>
        <source>Your name</source>
        <translation>Ihr Name</translation>
    </message>
    <message>
        <source>Create and sign in</source>
        <translation>Anlegen und anmelden</translation>
    </message>
    <message>
        <source>New trainee:</source>
        <translation>Neue(r) Auszubildende(r):</translation>
    </message>
    <message>
        <source>Instructor</source>
        <translation>Ausbilder(in)</translation>
    </message>
    <message>
        <source>Sign in as instructor</source>
        <translation>Als Ausbilder(in) anmelden</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Name</translation>
    </message>
    <message>
        <source>Password</source>
        <translation>Passwort</translation>
    </message>
    <message>
        <source>The history is unavailable: you can practise, but nothing will be stored.</source>
        <translation>Der Verlauf ist nicht verfügbar: Sie können üben, aber nichts wird gespeichert.</translation>
    </message>
    <message>
        <source>Guest</source>
        <translation>Gast</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Type a name first.</source>
        <translation>Geben Sie zuerst einen Namen ein.</translation>
    </message>
    <message>
        <source>A person called %1 already exists; pick them from the list.</source>
        <translation>Eine Person namens %1 gibt es bereits; wählen Sie sie aus der Liste.</translation>
    </message>
    <message>
        <source>The trainee could not be created (%1).</source>
        <translation>Die/der Auszubildende konnte nicht angelegt werden (%1).</translation>
    </message>
    <message>
        <source>Instructors need the history to sign in.</source>
        <translation>Ausbilder brauchen zum Anmelden den Verlauf.</translation>
    </message>
    <message>
        <source>Unknown instructor or wrong password.</source>
        <translation>Unbekannte(r) Ausbilder(in) oder falsches Passwort.</translation>
    </message>
    <message>
        <source>No instructor has been set up in this history yet. Create the first one: they can then add instructors and trainees.</source>
        <translation>In diesem Verlauf ist noch kein(e) Ausbilder(in) eingerichtet. Legen Sie die erste Person an: sie kann dann Ausbilder und Auszubildende hinzufügen.</translation>
    </message>
    <message>
        <source>Create instructor and sign in</source>
        <translation>Ausbilder(in) anlegen und anmelden</translation>
    </message>
</context>
<context>
    <name>microsim::gui::TrackerStatusWidget</name>
    <message>
        <source>Tracker connected</source>
        <translation>Tracker verbunden</translation>
    </message>
    <message>
        <source>Tracker not connected</source>
        <translation>Tracker nicht verbunden</translation>
    </message>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message numerus="yes">
        <source>%n dropped</source>
        <translation><numerusform>%n verworfen</numerusform><numerusform>%n verworfen</numerusform></translation>
    </message>
    <message>
        <source>No tracker</source>
        <translation>Kein Tracker</translation>
    </message>
</context>
<context>
    <name>microsim::gui::TraineeHistoryView</name>
    <message>
        <source>Attempt</source>
        <translation>Versuch</translation>
    </message>
    <message>
        <source>Finished</source>
        <translation>Beendet</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Modus</translation>
    </message>
    <message>
        <source>Score</source>
        <translation>Punkte</translation>
    </message>
    <message>
        <source>Passed</source>
        <translation>Bestanden</translation>
    </message>
    <message>
        <source>No finished attempts in this lesson yet.</source>
        <translation>Noch keine beendeten Versuche in dieser Lektion.</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>no</source>
        <translation>nein</translation>
    </message>
</context>
<context>
    <name>microsim::gui::Viewport</name>
    <message>
        <source>F1: keys</source>
        <translation>F1: Tasten</translation>
    </message>
    <message>
        <source>Left hand active</source>
        <translation>Linke Hand aktiv</translation>
    </message>
    <message>
        <source>Right hand active</source>
        <translation>Rechte Hand aktiv</translation>
    </message>
    <message>
        <source>Side view</source>
        <translation>Seitenansicht</translation>
    </message>
    <message>
        <source>Left hand: %1 · right hand: %2</source>
        <translation>Linke Hand: %1 · rechte Hand: %2</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>nichts</translation>
    </message>
    <message>
        <source>forceps</source>
        <translation>Pinzette</translation>
    </message>
    <message>
        <source>needle holder</source>
        <translation>Nadelhalter</translation>
    </message>
    <message>
        <source>scalpel</source>
        <translation>Skalpell</translation>
    </message>
    <message>
        <source>scissors</source>
        <translation>Schere</translation>
    </message>
</context>
<context>
    <name>microsim::gui::settings::SettingsDialog</name>
    <message>
        <source>Settings</source>
        <translation>Einstellungen</translation>
    </message>
    <message>
        <source>Scene default</source>
        <translation>Vorgabe der Szene</translation>
    </message>
    <message>
        <source>Takes effect at the next start.</source>
        <translation>Wirkt beim nächsten Start.</translation>
    </message>
</context>
<context>
    <name>microsim::gui::settings::Tunables</name>
    <message>
        <source>As the lesson's scene says</source>
        <translation>Wie in der Szene der Lektion</translation>
    </message>
    <message>
        <source>Quasi-static (the paper's)</source>
        <translation>Quasistatisch (wie im Artikel)</translation>
    </message>
    <message>
        <source>Newton with multigrid</source>
        <translation>Newton mit Mehrgitter</translation>
    </message>
    <message>
        <source>Implicit Euler</source>
        <translation>Implizites Euler-Verfahren</translation>
    </message>
    <message>
        <source>Tissue solver</source>
        <translation>Gewebelöser</translation>
    </message>
    <message>
        <source>The tissue solver of live attempts; graded replays use the same one.</source>
        <translation>Der Gewebelöser für Live-Versuche; bewertete Wiederholungen nutzen denselben.</translation>
    </message>
    <message>
        <source>Iteration budget</source>
        <translation>Iterationsbudget</translation>
    </message>
    <message>
        <source>Solver iterations per step; 0 keeps the scene's.</source>
        <translation>Löser-Iterationen pro Schritt; 0 behält die der Szene.</translation>
    </message>
    <message>
        <source>Mono</source>
        <translation>Mono</translation>
    </message>
    <message>
        <source>Quad-buffer stereo</source>
        <translation>Quad-Buffer-Stereo</translation>
    </message>
    <message>
        <source>Anaglyph (red/cyan)</source>
        <translation>Anaglyphe (rot/cyan)</translation>
    </message>
    <message>
        <source>Side by side</source>
        <translation>Nebeneinander</translation>
    </message>
    <message>
        <source>Stereo</source>
        <translation>Stereo</translation>
    </message>
    <message>
        <source>QWERTY / QWERTZ (W A S D, Q E)</source>
        <translation>QWERTY / QWERTZ (W A S D, Q E)</translation>
    </message>
    <message>
        <source>AZERTY (Z Q S D, A E)</source>
        <translation>AZERTY (Z Q S D, A E)</translation>
    </message>
    <message>
        <source>Key map</source>
        <translation>Tastenbelegung</translation>
    </message>
    <message>
        <source>Which letter keys move the tools; the arrows and Space stay the same.</source>
        <translation>Welche Buchstabentasten die Instrumente bewegen; Pfeiltasten und Leertaste bleiben gleich.</translation>
    </message>
    <message>
        <source>Millimetres</source>
        <translation>Millimeter</translation>
    </message>
    <message>
        <source>Micrometres</source>
        <translation>Mikrometer</translation>
    </message>
    <message>
        <source>Length units</source>
        <translation>Längeneinheit</translation>
    </message>
    <message>
        <source>Units of lengths on the results page.</source>
        <translation>Einheit der Längen auf der Ergebnisseite.</translation>
    </message>
    <message>
        <source>System default</source>
        <translation>Systemvorgabe</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Sprache</translation>
    </message>
    <message>
        <source>The interface language.</source>
        <translation>Die Sprache der Oberfläche.</translation>
    </message>
    <message>
        <source>How the microscope's two eyes are shown. Quad-buffer stereo is offered only where the display has left and right buffers.</source>
        <translation>Wie die beiden Augen des Mikroskops gezeigt werden. Quad-Buffer-Stereo wird nur angeboten, wo die Anzeige linke und rechte Puffer hat.</translation>
    </message>
</context>
<context>
    <name>microsim::i18n::EndProductWords</name>
    <message>
        <source>suture-line disruption</source>
        <translation>Unterbrechung der Nahtreihe</translation>
    </message>
    <message>
        <source>back-wall stitch</source>
        <translation>Hinterwandnaht</translation>
    </message>
    <message>
        <source>oblique stitch</source>
        <translation>schräge Naht</translation>
    </message>
    <message>
        <source>wide bite</source>
        <translation>zu weiter Stich</translation>
    </message>
    <message>
        <source>partial-thickness bite</source>
        <translation>Stich nicht durch die ganze Wand</translation>
    </message>
    <message>
        <source>unequal spacing</source>
        <translation>ungleicher Nahtabstand</translation>
    </message>
    <message>
        <source>wall tear</source>
        <translation>Wandeinriss</translation>
    </message>
    <message>
        <source>over-tight stitch</source>
        <translation>zu fest geknüpfte Naht</translation>
    </message>
    <message>
        <source>thread in the lumen</source>
        <translation>Faden im Lumen</translation>
    </message>
    <message>
        <source>large edge overlap</source>
        <translation>große Randüberlappung</translation>
    </message>
</context>
<context>
    <name>microsim::tracking::GamepadSource</name>
    <message>
        <source>The game controller cannot be read: SDL did not start (%1).</source>
        <translation>Der Gamecontroller kann nicht gelesen werden: SDL ist nicht gestartet (%1).</translation>
    </message>
    <message>
        <source>No game controller found: connect one (USB or Bluetooth) and try again.</source>
        <translation>Kein Gamecontroller gefunden: einen anschließen (USB oder Bluetooth) und erneut versuchen.</translation>
    </message>
    <message>
        <source>The game controller %1 was disconnected.</source>
        <translation>Der Gamecontroller %1 wurde getrennt.</translation>
    </message>
</context>
<context>
    <name>microsim::tracking::ManualSource</name>
    <message>
        <source>Tab — switch hand</source>
        <translation>Tab — Hand wechseln</translation>
    </message>
    <message>
        <source>A / D — move left / right</source>
        <translation>A / D — nach links / rechts bewegen</translation>
    </message>
    <message>
        <source>W / S — move up / down</source>
        <translation>W / S — nach oben / unten bewegen</translation>
    </message>
    <message>
        <source>Q / E — move away / toward you</source>
        <translation>Q / E — von Ihnen weg / zu Ihnen hin bewegen</translation>
    </message>
    <message>
        <source>← / → — turn the tool</source>
        <translation>← / → — Instrument drehen</translation>
    </message>
    <message>
        <source>↑ / ↓ — tilt the tool</source>
        <translation>↑ / ↓ — Instrument neigen</translation>
    </message>
    <message>
        <source>Space (hold) — close the jaws</source>
        <translation>Leertaste (halten) — Branchen schließen</translation>
    </message>
    <message>
        <source>Shift — fine steps</source>
        <translation>Umschalt — feine Schritte</translation>
    </message>
    <message>
        <source>R — reset the tools</source>
        <translation>R — Instrumente zurücksetzen</translation>
    </message>
    <message>
        <source>F1 — show or hide this help</source>
        <translation>F1 — diese Hilfe ein- oder ausblenden</translation>
    </message>
    <message>
        <source>Z / X — turn the held needle back / forward along its curve</source>
        <translation>Z / X — gehaltene Nadel entlang ihrer Krümmung zurück / vorwärts drehen</translation>
    </message>
    <message>
        <source>C / V — close / open the jaws a step</source>
        <translation>C / V — Branchen schrittweise schließen / öffnen</translation>
    </message>
    <message>
        <source>Left drag — move the tool in the view plane; wheel — move it in depth</source>
        <translation>Links ziehen — Instrument in der Bildebene bewegen; Rad — in der Tiefe bewegen</translation>
    </message>
    <message>
        <source>Ctrl + left drag or Ctrl + wheel — turn the held needle along its curve</source>
        <translation>Strg + links ziehen oder Strg + Rad — gehaltene Nadel entlang ihrer Krümmung drehen</translation>
    </message>
    <message>
        <source>Ctrl + left drag without a needle — turn the tool</source>
        <translation>Strg + links ziehen ohne Nadel — Instrument drehen</translation>
    </message>
    <message>
        <source>Right drag down / up — close / open the jaws; right click — close or open them</source>
        <translation>Rechts nach unten / oben ziehen — Branchen schließen / öffnen; Rechtsklick — schließen oder öffnen</translation>
    </message>
    <message>
        <source>Middle drag or Shift + left drag — orbit; Shift + middle drag — pan</source>
        <translation>Mitte ziehen oder Umschalt + links ziehen — umkreisen; Umschalt + Mitte ziehen — verschieben</translation>
    </message>
    <message>
        <source>Shift + wheel — zoom; Alt + wheel — focus</source>
        <translation>Umschalt + Rad — zoomen; Alt + Rad — fokussieren</translation>
    </message>
    <message>
        <source>Home — microscope view; 1 / 2 / 3 — top / oblique / side view</source>
        <translation>Pos1 — Mikroskopansicht; 1 / 2 / 3 — Ansicht von oben / schräg / von der Seite</translation>
    </message>
    <message>
        <source>T — take up the scissors or the forceps (the jaw keys and buttons close either)</source>
        <translation>T — Schere oder Pinzette aufnehmen (die Tasten und Knöpfe für die Branchen schließen beide)</translation>
    </message>
</context>
<context>
    <name>microsim::tracking::SpacenavSource</name>
    <message>
        <source>No 3D mouse: spacenavd, the 3D mouse's daemon, is not running or cannot be reached (install and start spacenavd, then try again).</source>
        <translation>Keine 3D-Maus: spacenavd, der Dienst der 3D-Maus, läuft nicht oder ist nicht erreichbar (spacenavd installieren und starten, dann erneut versuchen).</translation>
    </message>
    <message>
        <source>The 3D mouse's daemon (spacenavd) closed the connection.</source>
        <translation>Der Dienst der 3D-Maus (spacenavd) hat die Verbindung geschlossen.</translation>
    </message>
</context>
</TS>