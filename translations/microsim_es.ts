<?xml version='1.0' encoding='utf-8'?>
<TS version="2.1" language="es">
<context>
    <name>Cli</name>
    <message>
        <source>Write the rows as JSON to &lt;file&gt;.</source>
        <translation>Escribir las filas como JSON en &lt;file&gt;.</translation>
    </message>
    <message>
        <source>Draw the curves to the PNG &lt;file&gt;.</source>
        <translation>Dibujar las curvas en el PNG &lt;file&gt;.</translation>
    </message>
    <message>
        <source>Smaller sizes and fewer repetitions.</source>
        <translation>Tamaños menores y menos repeticiones.</translation>
    </message>
    <message>
        <source>List the benchmarks.</source>
        <translation>Listar los benchmarks.</translation>
    </message>
    <message>
        <source>Show this help.</source>
        <translation>Mostrar esta ayuda.</translation>
    </message>
    <message>
        <source>The benchmark to run.</source>
        <translation>El benchmark que se ejecutará.</translation>
    </message>
    <message>
        <source>Usage: microsim-cli bench NAME [--json FILE] [--plot FILE.png] [--quick]</source>
        <translation>Uso: microsim-cli bench NOMBRE [--json ARCHIVO] [--plot ARCHIVO.png] [--quick]</translation>
    </message>
    <message>
        <source>Benchmarks:</source>
        <translation>Benchmarks:</translation>
    </message>
    <message>
        <source>run a benchmark (beside the paper's figures)</source>
        <translation>ejecutar un benchmark (junto a las cifras del artículo)</translation>
    </message>
    <message>
        <source>Usage: microsim-cli &lt;command&gt; [options]</source>
        <translation>Uso: microsim-cli &lt;orden&gt; [opciones]</translation>
    </message>
    <message>
        <source>       microsim-cli --version | --help</source>
        <translation>    microsim-cli --version | --help</translation>
    </message>
    <message>
        <source>Commands:</source>
        <translation>Órdenes:</translation>
    </message>
    <message>
        <source>Run 'microsim-cli &lt;command&gt; --help' for a command's options.</source>
        <translation>Ejecute «microsim-cli &lt;orden&gt; --help» para ver las opciones de una orden.</translation>
    </message>
    <message>
        <source>microsim-cli: unknown command '%1'</source>
        <translation>microsim-cli: orden desconocida «%1»</translation>
    </message>
    <message>
        <source>solve a spring network (scene file or lattice box)</source>
        <translation>resolver una red de muelles (archivo de escena o cubo reticular)</translation>
    </message>
    <message>
        <source>export the spring network a scene builds</source>
        <translation>exportar la red de muelles que construye una escena</translation>
    </message>
    <message>
        <source>Write the network as JSON to &lt;file&gt;.</source>
        <translation>Escribir la red como JSON en &lt;file&gt;.</translation>
    </message>
    <message>
        <source>Usage: microsim-cli export --scene FILE | --lattice N [--json FILE]</source>
        <translation>Uso: microsim-cli export --scene ARCHIVO | --lattice N [--json ARCHIVO]</translation>
    </message>
    <message>
        <source>unexpected argument '%1'</source>
        <translation>argumento inesperado «%1»</translation>
    </message>
    <message>
        <source>objects</source>
        <translation>objetos</translation>
    </message>
    <message>
        <source>nodes</source>
        <translation>nodos</translation>
    </message>
    <message>
        <source>links</source>
        <translation>muelles</translation>
    </message>
    <message>
        <source>fixed</source>
        <translation>fijos</translation>
    </message>
    <message>
        <source>controls</source>
        <translation>nodos de control</translation>
    </message>
    <message>
        <source>triangles</source>
        <translation>triángulos</translation>
    </message>
    <message>
        <source>cannot write %1: %2</source>
        <translation>no se puede escribir %1: %2</translation>
    </message>
    <message>
        <source>converged</source>
        <translation>convergido</translation>
    </message>
    <message>
        <source>iteration limit</source>
        <translation>límite de iteraciones</translation>
    </message>
    <message>
        <source>time limit</source>
        <translation>límite de tiempo</translation>
    </message>
    <message>
        <source>diverged (state restored)</source>
        <translation>divergió (estado restaurado)</translation>
    </message>
    <message>
        <source>invalid input</source>
        <translation>entrada no válida</translation>
    </message>
    <message>
        <source>--%1 wants a number in [%2, %3), not '%4'</source>
        <translation>--%1 espera un número en [%2, %3), no «%4»</translation>
    </message>
    <message>
        <source>The solver: %1 (default: the scene's, else qss).</source>
        <translation>El solucionador: %1 (predeterminado: el de la escena, si no qss).</translation>
    </message>
    <message>
        <source>Stop after &lt;k&gt; iterations.</source>
        <translation>Parar tras &lt;k&gt; iteraciones.</translation>
    </message>
    <message>
        <source>Stop after &lt;t&gt; milliseconds of wall-clock time.</source>
        <translation>Parar tras &lt;t&gt; milisegundos de tiempo real.</translation>
    </message>
    <message>
        <source>qss per-level cutout ε in mm (0 = off).</source>
        <translation>corte por nivel ε de qss en mm (0 = desactivado).</translation>
    </message>
    <message>
        <source>qss step scale in mm per force unit (0 = automatic).</source>
        <translation>escala de paso de qss en mm por unidad de fuerza (0 = automática).</translation>
    </message>
    <message>
        <source>qss momentum β in [0, 1).</source>
        <translation>momento β de qss en [0, 1).</translation>
    </message>
    <message>
        <source>Stop once the relative residual is below &lt;r&gt;.</source>
        <translation>Parar cuando el residuo relativo sea menor que &lt;r&gt;.</translation>
    </message>
    <message>
        <source>Write positions and the report as JSON to &lt;file&gt;.</source>
        <translation>Escribir las posiciones y el informe como JSON en &lt;file&gt;.</translation>
    </message>
    <message>
        <source>Usage: microsim-cli solve --scene FILE | --lattice N [--solver NAME] (--iterations K | --budget-ms T) [options]</source>
        <translation>Uso: microsim-cli solve --scene ARCHIVO | --lattice N [--solver NOMBRE] (--iterations K | --budget-ms T) [opciones]</translation>
    </message>
    <message>
        <source>--iterations wants a whole number ≥ 1, not '%1'</source>
        <translation>--iterations espera un número entero ≥ 1, no «%1»</translation>
    </message>
    <message>
        <source>unknown solver '%1' (known: %2)</source>
        <translation>solucionador desconocido «%1» (conocidos: %2)</translation>
    </message>
    <message>
        <source>the scene names an unknown solver '%1'</source>
        <translation>la escena indica un solucionador desconocido «%1»</translation>
    </message>
    <message>
        <source>give --iterations K or --budget-ms T (or put them in the scene's "solver")</source>
        <translation>indique --iterations K o --budget-ms T (o póngalos en el «solver» de la escena)</translation>
    </message>
    <message>
        <source>solver</source>
        <translation>solucionador</translation>
    </message>
    <message>
        <source>iterations</source>
        <translation>iteraciones</translation>
    </message>
    <message>
        <source>seconds</source>
        <translation>segundos</translation>
    </message>
    <message>
        <source>residual</source>
        <translation>residuo</translation>
    </message>
    <message>
        <source>status</source>
        <translation>estado</translation>
    </message>
    <message>
        <source>cannot open the scene file</source>
        <translation>no se puede abrir el archivo de escena</translation>
    </message>
    <message>
        <source>not valid JSON</source>
        <translation>no es JSON válido</translation>
    </message>
    <message>
        <source>wrong type or length</source>
        <translation>tipo o longitud incorrectos</translation>
    </message>
    <message>
        <source>required field missing</source>
        <translation>falta un campo obligatorio</translation>
    </message>
    <message>
        <source>unknown field</source>
        <translation>campo desconocido</translation>
    </message>
    <message>
        <source>unknown object type</source>
        <translation>tipo de objeto desconocido</translation>
    </message>
    <message>
        <source>node index out of range</source>
        <translation>índice de nodo fuera de rango</translation>
    </message>
    <message>
        <source>link joins a node to itself</source>
        <translation>el muelle une un nodo consigo mismo</translation>
    </message>
    <message>
        <source>value must not be negative</source>
        <translation>el valor no puede ser negativo</translation>
    </message>
    <message>
        <source>number is not finite</source>
        <translation>el número no es finito</translation>
    </message>
    <message>
        <source>node is controlled twice</source>
        <translation>el nodo se controla dos veces</translation>
    </message>
    <message>
        <source>value out of range</source>
        <translation>valor fuera de rango</translation>
    </message>
    <message>
        <source>cannot import the surface mesh</source>
        <translation>no se puede importar la malla de superficie</translation>
    </message>
    <message>
        <source>file not found</source>
        <translation>archivo no encontrado</translation>
    </message>
    <message>
        <source>unreadable</source>
        <translation>ilegible</translation>
    </message>
    <message>
        <source>no triangles</source>
        <translation>sin triángulos</translation>
    </message>
    <message>
        <source>non-finite coordinates</source>
        <translation>coordenadas no finitas</translation>
    </message>
    <message>
        <source>bad import options</source>
        <translation>opciones de importación no válidas</translation>
    </message>
    <message>
        <source>(field %1)</source>
        <translation>(campo %1)</translation>
    </message>
    <message>
        <source>give exactly one of --scene FILE and --lattice N</source>
        <translation>indique exactamente uno de --scene ARCHIVO y --lattice N</translation>
    </message>
    <message>
        <source>--stiffness applies to --lattice only</source>
        <translation>--stiffness solo se aplica a --lattice</translation>
    </message>
    <message>
        <source>--lattice wants a whole number from 2 to 200, not '%1'</source>
        <translation>--lattice espera un número entero de 2 a 200, no «%1»</translation>
    </message>
    <message>
        <source>--stiffness wants a number ≥ 0, not '%1'</source>
        <translation>--stiffness espera un número ≥ 0, no «%1»</translation>
    </message>
    <message>
        <source>Read the spring network from the scene &lt;file&gt;.</source>
        <translation>Leer la red de muelles de la escena &lt;file&gt;.</translation>
    </message>
    <message>
        <source>Use the paper's N×N×N lattice box (bottom fixed, top middle node pulled up 1 mm).</source>
        <translation>Usar el cubo reticular N×N×N del artículo (base fija, nodo central superior desplazado 1 mm hacia arriba).</translation>
    </message>
    <message>
        <source>Link stiffness of the --lattice box in g/s² (default 10).</source>
        <translation>Rigidez de los muelles del cubo --lattice en g/s² (predeterminada 10).</translation>
    </message>
    <message>
        <source>each pose must be 16 numbers (a 4 by 4 matrix, row-major)</source>
        <translation>cada pose debe tener 16 números (una matriz 4×4, por filas)</translation>
    </message>
    <message>
        <source>each fiducial and check point needs "tracker" and "scene" as [x, y, z]</source>
        <translation>cada punto fiducial y de control necesita «tracker» y «scene» como [x, y, z]</translation>
    </message>
    <message>
        <source>Read the poses or points from the JSON &lt;file&gt;.</source>
        <translation>Leer las poses o los puntos del JSON &lt;file&gt;.</translation>
    </message>
    <message>
        <source>Write the result as JSON to &lt;file&gt;.</source>
        <translation>Escribir el resultado como JSON en &lt;file&gt;.</translation>
    </message>
    <message>
        <source>pivot or register</source>
        <translation>pivot o register</translation>
    </message>
    <message>
        <source>run a scene on recorded or scripted input (hash, events, timings)</source>
        <translation>ejecutar una escena con entrada grabada o programada (hash, eventos, tiempos)</translation>
    </message>
    <message>
        <source>record what an OpenIGTLink tracker sends</source>
        <translation>grabar lo que envía un localizador OpenIGTLink</translation>
    </message>
    <message>
        <source>pivot calibration or tracker-to-scene registration from a file</source>
        <translation>calibración de pivote o registro localizador-escena desde un archivo</translation>
    </message>
    <message numerus="yes">
        <source>forceps grabs %n tissue node(s)</source>
        <translation><numerusform>la pinza sujeta %n nodo de tejido</numerusform><numerusform>la pinza sujeta %n nodos de tejido</numerusform></translation>
    </message>
    <message numerus="yes">
        <source>forceps releases %n tissue node(s)</source>
        <translation><numerusform>la pinza suelta %n nodo de tejido</numerusform><numerusform>la pinza suelta %n nodos de tejido</numerusform></translation>
    </message>
    <message>
        <source>forceps grips the suture at node %1</source>
        <translation>la pinza sujeta la sutura en el nodo %1</translation>
    </message>
    <message>
        <source>forceps lets go of the suture</source>
        <translation>la pinza suelta la sutura</translation>
    </message>
    <message>
        <source>needle enters a wall</source>
        <translation>la aguja entra en una pared</translation>
    </message>
    <message>
        <source>needle leaves a wall</source>
        <translation>la aguja sale de una pared</translation>
    </message>
    <message numerus="yes">
        <source>scalpel cuts %n link(s)</source>
        <translation><numerusform>el bisturí corta %n muelle</numerusform><numerusform>el bisturí corta %n muelles</numerusform></translation>
    </message>
    <message>
        <source>suture breaks at link %1</source>
        <translation>la sutura se rompe en el eslabón %1</translation>
    </message>
    <message>
        <source>suture slips out of a pierce</source>
        <translation>la sutura se sale de una punción</translation>
    </message>
    <message>
        <source>needle leaves a pierce before the thread reaches it</source>
        <translation>la aguja sale de una punción antes de que el hilo llegue a ella</translation>
    </message>
    <message>
        <source>input frame rejected</source>
        <translation>fotograma de entrada rechazado</translation>
    </message>
    <message>
        <source>cannot open the recording</source>
        <translation>no se puede abrir la grabación</translation>
    </message>
    <message>
        <source>cannot write the recording</source>
        <translation>no se puede escribir la grabación</translation>
    </message>
    <message>
        <source>not a microsim recording</source>
        <translation>no es una grabación de microsim</translation>
    </message>
    <message>
        <source>recording from a newer version</source>
        <translation>grabación de una versión más reciente</translation>
    </message>
    <message>
        <source>unfinished recording (no end record)</source>
        <translation>grabación incompleta (sin registro final)</translation>
    </message>
    <message>
        <source>damaged recording (checksum mismatch)</source>
        <translation>grabación dañada (la suma de comprobación no coincide)</translation>
    </message>
    <message>
        <source>damaged recording (malformed frame)</source>
        <translation>grabación dañada (fotograma mal formado)</translation>
    </message>
    <message>
        <source>Replay the input frames of the recording &lt;file&gt;.</source>
        <translation>Reproducir los fotogramas de entrada de la grabación &lt;file&gt;.</translation>
    </message>
    <message>
        <source>Generate the input instead: 'stitch' (one scripted stitch) or 'back-wall-catch' (a pass that catches the back wall).</source>
        <translation>Generar la entrada en su lugar: «stitch» (un punto programado) o «back-wall-catch» (un pase que toma la pared posterior).</translation>
    </message>
    <message>
        <source>Record every input frame to &lt;file&gt;.</source>
        <translation>Grabar cada fotograma de entrada en &lt;file&gt;.</translation>
    </message>
    <message>
        <source>Run &lt;n&gt; steps (default: every input frame, else 100).</source>
        <translation>Ejecutar &lt;n&gt; pasos (predeterminado: cada fotograma de entrada, si no 100).</translation>
    </message>
    <message>
        <source>Stop each tissue solve at the step budget (not reproducible).</source>
        <translation>Detener cada resolución del tejido en el presupuesto del paso (no reproducible).</translation>
    </message>
    <message>
        <source>Write the hash, events and timings as JSON to &lt;file&gt;.</source>
        <translation>Escribir el hash, los eventos y los tiempos como JSON en &lt;file&gt;.</translation>
    </message>
    <message>
        <source>--input and --script exclude each other</source>
        <translation>--input y --script se excluyen mutuamente</translation>
    </message>
    <message>
        <source>unknown script '%1' (known: %2)</source>
        <translation>guion desconocido «%1» (conocidos: %2)</translation>
    </message>
    <message>
        <source>--frames wants a whole number ≥ 0, not '%1'</source>
        <translation>--frames espera un número entero ≥ 0, no «%1»</translation>
    </message>
    <message numerus="yes">
        <source>replaying its %n complete frame(s)</source>
        <translation><numerusform>se reproduce su %n fotograma completo</numerusform><numerusform>se reproducen sus %n fotogramas completos</numerusform></translation>
    </message>
    <message>
        <source>(at byte %1)</source>
        <translation>(en el byte %1)</translation>
    </message>
    <message>
        <source>the script '%1' needs a severed vessel, a curved needle and two forceps</source>
        <translation>el guion «%1» necesita un vaso seccionado, una aguja curva y dos pinzas</translation>
    </message>
    <message>
        <source>scene</source>
        <translation>escena</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>pasos</translation>
    </message>
    <message>
        <source> of %1 s</source>
        <translation> de %1 s</translation>
    </message>
    <message>
        <source>state hash</source>
        <translation>hash del estado</translation>
    </message>
    <message>
        <source>events</source>
        <translation>eventos</translation>
    </message>
    <message>
        <source>end %1, angle %2°, bite %3 mm, at (%4, %5, %6)</source>
        <translation>extremo %1, ángulo %2°, distancia al borde %3 mm, en (%4, %5, %6)</translation>
    </message>
    <message>
        <source>collision</source>
        <translation>colisión</translation>
    </message>
    <message>
        <source>tissue</source>
        <translation>tejido</translation>
    </message>
    <message>
        <source>suture</source>
        <translation>sutura</translation>
    </message>
    <message>
        <source>interactions</source>
        <translation>interacciones</translation>
    </message>
    <message>
        <source>total</source>
        <translation>total</translation>
    </message>
    <message>
        <source>step time (ms)</source>
        <translation>tiempo por paso (ms)</translation>
    </message>
    <message>
        <source>median</source>
        <translation>mediana</translation>
    </message>
    <message>
        <source>p99</source>
        <translation>p99</translation>
    </message>
    <message>
        <source>max</source>
        <translation>máx.</translation>
    </message>
    <message>
        <source>OpenIGTLink server to read, HOST:PORT (port 18944 by default).</source>
        <translation>Servidor OpenIGTLink que leer, HOST:PUERTO (puerto 18944 por defecto).</translation>
    </message>
    <message>
        <source>Record for &lt;seconds&gt; (default 10).</source>
        <translation>Grabar durante &lt;seconds&gt; segundos (predeterminado 10).</translation>
    </message>
    <message>
        <source>Write the record as JSON to &lt;file&gt;.</source>
        <translation>Escribir la grabación como JSON en &lt;file&gt;.</translation>
    </message>
    <message>
        <source>Stop when the server closes the link (no reconnection).</source>
        <translation>Parar cuando el servidor cierre el enlace (sin reconexión).</translation>
    </message>
    <message>
        <source>Refuse poses moving faster than &lt;mm/s&gt; (default 2000).</source>
        <translation>Rechazar poses que se muevan más rápido que &lt;mm/s&gt; (predeterminado 2000).</translation>
    </message>
    <message>
        <source>%1 connection(s) to %2:%3</source>
        <translation>%1 conexión(es) a %2:%3</translation>
    </message>
    <message>
        <source>device              received   rate (Hz)   last position (mm)</source>
        <translation>dispositivo         recibidas  tasa (Hz)   última posición (mm)</translation>
    </message>
    <message>
        <source>rejected: %1</source>
        <translation>rechazadas: %1</translation>
    </message>
    <message>
        <source>sample %1 of the tracker stream: bad "%2"</source>
        <translation>muestra %1 del flujo del rastreador: «%2» incorrecto</translation>
    </message>
    <message>
        <source>not a tracker stream this version reads</source>
        <translation>no es un flujo del rastreador que esta versión lea</translation>
    </message>
    <message>
        <source>choose the device with --device (the stream holds: %1)</source>
        <translation>elija el dispositivo con --device (el flujo contiene: %1)</translation>
    </message>
    <message>
        <source>pivot on a tracker stream: the device to calibrate.</source>
        <translation>pivot sobre un flujo del rastreador: el dispositivo que se calibra.</translation>
    </message>
    <message>
        <source>Usage: microsim-cli calibrate pivot|register --input FILE [--device NAME] [--json FILE]</source>
        <translation>Uso: microsim-cli calibrate pivot|register --input ARCHIVO [--device NOMBRE] [--json ARCHIVO]</translation>
    </message>
    <message>
        <source>score a recorded attempt with a rubric (and store it in the history)</source>
        <translation>evaluar un intento grabado con una rúbrica (y guardarlo en el historial)</translation>
    </message>
    <message>
        <source>the history database: migrate, backup, restore, export CSV, trainees</source>
        <translation>la base de datos del historial: migrar, copia de seguridad, restaurar, exportar CSV, residentes</translation>
    </message>
    <message>
        <source>cannot create the folder for %1</source>
        <translation>no se puede crear la carpeta para %1</translation>
    </message>
    <message>
        <source>cannot open %1</source>
        <translation>no se puede abrir %1</translation>
    </message>
    <message>
        <source>%1 is not a microsim database or is damaged; it was left untouched</source>
        <translation>%1 no es una base de datos de microsim o está dañada; no se ha modificado</translation>
    </message>
    <message>
        <source>%1 is locked by another program</source>
        <translation>%1 está bloqueada por otro programa</translation>
    </message>
    <message>
        <source>%1 was written by a newer microsim</source>
        <translation>%1 fue escrita por una versión más reciente de microsim</translation>
    </message>
    <message>
        <source>updating %1 failed; it was left as it was</source>
        <translation>la actualización de %1 falló; se dejó como estaba</translation>
    </message>
    <message>
        <source>%1 is read-only; it was left untouched</source>
        <translation>%1 es de solo lectura; no se ha modificado</translation>
    </message>
    <message>
        <source>the database is not open</source>
        <translation>la base de datos no está abierta</translation>
    </message>
    <message>
        <source>not allowed for this user</source>
        <translation>no permitido para este usuario</translation>
    </message>
    <message>
        <source>no such person or attempt</source>
        <translation>no existe esa persona o ese intento</translation>
    </message>
    <message>
        <source>the attempt is already finished</source>
        <translation>el intento ya está terminado</translation>
    </message>
    <message>
        <source>that name is taken</source>
        <translation>ese nombre ya está en uso</translation>
    </message>
    <message>
        <source>empty name, or a password shorter than %1 characters</source>
        <translation>nombre vacío o contraseña de menos de %1 caracteres</translation>
    </message>
    <message>
        <source>unknown instructor or wrong password</source>
        <translation>instructor desconocido o contraseña incorrecta</translation>
    </message>
    <message>
        <source>not possible on a PostgreSQL server (use pg_dump and pg_restore there)</source>
        <translation>no es posible en un servidor PostgreSQL (use allí pg_dump y pg_restore)</translation>
    </message>
    <message>
        <source>the file is not a microsim history</source>
        <translation>el archivo no es un historial de microsim</translation>
    </message>
    <message>
        <source>the backup was written by a newer microsim</source>
        <translation>la copia de seguridad fue escrita por una versión más reciente de microsim</translation>
    </message>
    <message>
        <source>the database reported an error</source>
        <translation>la base de datos informó de un error</translation>
    </message>
    <message>
        <source>instructor</source>
        <translation>instructor</translation>
    </message>
    <message>
        <source>trainee</source>
        <translation>residente</translation>
    </message>
    <message>
        <source>The history: an SQLite &lt;file&gt; or a postgresql://user@host:port/db URL.</source>
        <translation>El historial: un archivo SQLite &lt;file&gt; o una URL postgresql://user@host:port/db.</translation>
    </message>
    <message>
        <source>add-trainee: the trainee's &lt;group&gt;.</source>
        <translation>add-trainee: el grupo &lt;group&gt; del residente.</translation>
    </message>
    <message>
        <source>export-csv: sign in as instructor &lt;name&gt; (password on stdin).</source>
        <translation>export-csv: iniciar sesión como instructor &lt;name&gt; (contraseña por stdin).</translation>
    </message>
    <message>
        <source>add-instructor: read the password from standard input.</source>
        <translation>add-instructor: leer la contraseña de la entrada estándar.</translation>
    </message>
    <message>
        <source>list-trainees: also write JSON to &lt;file&gt;.</source>
        <translation>list-trainees: escribir también JSON en &lt;file&gt;.</translation>
    </message>
    <message>
        <source>Usage: microsim-cli db migrate|backup FILE|restore FILE|export-csv FILE --instructor NAME|list-trainees|add-trainee NAME [--group G]|add-instructor NAME --password-stdin [--db FILE_OR_URL]</source>
        <translation>Uso: microsim-cli db migrate|backup ARCHIVO|restore ARCHIVO|export-csv ARCHIVO --instructor NOMBRE|list-trainees|add-trainee NOMBRE [--group G]|add-instructor NOMBRE --password-stdin [--db ARCHIVO_O_URL]</translation>
    </message>
    <message>
        <source>%1: schema version %2</source>
        <translation>%1: versión de esquema %2</translation>
    </message>
    <message>
        <source>backed up %1 to %2</source>
        <translation>copia de seguridad de %1 en %2</translation>
    </message>
    <message>
        <source>restored %1 from %2 (schema version %3)</source>
        <translation>%1 restaurada desde %2 (versión de esquema %3)</translation>
    </message>
    <message>
        <source>wrote %1</source>
        <translation>escrito %1</translation>
    </message>
    <message>
        <source>id</source>
        <translation>id</translation>
    </message>
    <message>
        <source>role</source>
        <translation>rol</translation>
    </message>
    <message>
        <source>group</source>
        <translation>grupo</translation>
    </message>
    <message>
        <source>name</source>
        <translation>nombre</translation>
    </message>
    <message>
        <source>added trainee %1 (id %2)</source>
        <translation>residente %1 añadido (id %2)</translation>
    </message>
    <message>
        <source>added instructor %1 (id %2)</source>
        <translation>instructor %1 añadido (id %2)</translation>
    </message>
    <message>
        <source>tissue link %1 over-stretched (%2 %)</source>
        <translation>enlace de tejido %1 sobreestirado (%2 %)</translation>
    </message>
    <message numerus="yes">
        <source>tissue tears: %n link(s) removed</source>
        <translation><numerusform>el tejido se desgarra: %n enlace eliminado</numerusform><numerusform>el tejido se desgarra: %n enlaces eliminados</numerusform></translation>
    </message>
    <message>
        <source>cannot open the rubric file</source>
        <translation>no se puede abrir el archivo de rúbrica</translation>
    </message>
    <message>
        <source>wrong type</source>
        <translation>tipo incorrecto</translation>
    </message>
    <message>
        <source>missing field</source>
        <translation>falta un campo</translation>
    </message>
    <message>
        <source>unknown metric</source>
        <translation>métrica desconocida</translation>
    </message>
    <message>
        <source>invalid value</source>
        <translation>valor no válido</translation>
    </message>
    <message>
        <source>rubric</source>
        <translation>rúbrica</translation>
    </message>
    <message>
        <source>version %1, pass mark %2</source>
        <translation>versión %1, nota de aprobado %2</translation>
    </message>
    <message>
        <source>recording</source>
        <translation>grabación</translation>
    </message>
    <message numerus="yes">
        <source>%n frame(s)</source>
        <translation><numerusform>%n fotograma</numerusform><numerusform>%n fotogramas</numerusform></translation>
    </message>
    <message>
        <source>(unfinished: scored as far as it goes)</source>
        <translation>(incompleta: evaluada hasta donde llega)</translation>
    </message>
    <message>
        <source>score</source>
        <translation>puntuación</translation>
    </message>
    <message>
        <source>passed</source>
        <translation>aprobado</translation>
    </message>
    <message>
        <source>not passed</source>
        <translation>no aprobado</translation>
    </message>
    <message>
        <source>never-event</source>
        <translation>evento nunca admisible</translation>
    </message>
    <message>
        <source>metric</source>
        <translation>métrica</translation>
    </message>
    <message>
        <source>value</source>
        <translation>valor</translation>
    </message>
    <message>
        <source>unit</source>
        <translation>unidad</translation>
    </message>
    <message>
        <source>target</source>
        <translation>objetivo</translation>
    </message>
    <message>
        <source>weight</source>
        <translation>peso</translation>
    </message>
    <message>
        <source>points</source>
        <translation>puntos</translation>
    </message>
    <message>
        <source>feedback</source>
        <translation>comentario</translation>
    </message>
    <message>
        <source>pierces</source>
        <translation>punciones</translation>
    </message>
    <message>
        <source>none</source>
        <translation>ninguna</translation>
    </message>
    <message>
        <source>%1 s, end %2, %3 → %4, entry %5°, exit %6°, bite %7 mm, at %8°</source>
        <translation>%1 s, extremo %2, %3 → %4, entrada %5°, salida %6°, distancia al borde %7 mm, a %8°</translation>
    </message>
    <message>
        <source>full thickness</source>
        <translation>espesor completo</translation>
    </message>
    <message>
        <source>back wall</source>
        <translation>pared posterior</translation>
    </message>
    <message>
        <source>cannot store the attempt: %1</source>
        <translation>no se puede guardar el intento: %1</translation>
    </message>
    <message>
        <source>The recording &lt;file&gt; to score.</source>
        <translation>La grabación &lt;file&gt; que se evalúa.</translation>
    </message>
    <message>
        <source>The rubric &lt;file&gt; that grades it.</source>
        <translation>La rúbrica &lt;file&gt; con la que se evalúa.</translation>
    </message>
    <message>
        <source>The scene &lt;file&gt; (default: the one the recording names).</source>
        <translation>La escena &lt;file&gt; (por defecto: la que indica la grabación).</translation>
    </message>
    <message>
        <source>Store the attempt in the history database &lt;file or URL&gt;.</source>
        <translation>Guardar el intento en la base de datos de historial &lt;file or URL&gt;.</translation>
    </message>
    <message>
        <source>The trainee the attempt belongs to (with --db; added when new).</source>
        <translation>El alumno al que pertenece el intento (con --db; se crea si es nuevo).</translation>
    </message>
    <message>
        <source>The lesson stored with the attempt (default: the rubric's id).</source>
        <translation>La lección que se guarda con el intento (por defecto: el identificador de la rúbrica).</translation>
    </message>
    <message>
        <source>The attempt's mode stored with --db: learn or test (default test).</source>
        <translation>El modo del intento que se guarda con --db: learn o test (por defecto test).</translation>
    </message>
    <message>
        <source>Write the score, metrics and pierces as JSON to &lt;file&gt;.</source>
        <translation>Escribir la puntuación, las métricas y las punciones como JSON en &lt;file&gt;.</translation>
    </message>
    <message>
        <source>Usage: microsim-cli score --recording REC --rubric FILE [--scene FILE] [--db FILE --trainee NAME [--lesson ID] [--mode learn|test]] [--json OUT]</source>
        <translation>Uso: microsim-cli score --recording REC --rubric FILE [--scene FILE] [--db FILE --trainee NAME [--lesson ID] [--mode learn|test]] [--json OUT]</translation>
    </message>
    <message>
        <source>--recording REC and --rubric FILE are required</source>
        <translation>--recording REC y --rubric FILE son obligatorios</translation>
    </message>
    <message>
        <source>--db and --trainee go together</source>
        <translation>--db y --trainee van juntos</translation>
    </message>
    <message>
        <source>--mode is learn or test, not '%1'</source>
        <translation>--mode es learn o test, no '%1'</translation>
    </message>
    <message numerus="yes">
        <source>scoring its %n complete frame(s)</source>
        <translation><numerusform>se evalúa su %n fotograma completo</numerusform><numerusform>se evalúan sus %n fotogramas completos</numerusform></translation>
    </message>
    <message>
        <source>the recording names no scene: give --scene FILE</source>
        <translation>la grabación no indica ninguna escena: indique --scene FILE</translation>
    </message>
    <message>
        <source>stored as attempt %1</source>
        <translation>guardado como intento %1</translation>
    </message>
    <message>
        <source>Write every accepted pose and channel value as a tracker stream to &lt;file&gt;.</source>
        <translation>Escribir cada pose y valor de canal aceptados como flujo del rastreador en &lt;file&gt;.</translation>
    </message>
    <message>
        <source>Usage: microsim-cli track --igtl HOST:PORT [--duration S] [--json FILE] [--record FILE] [--once] [--max-speed MM_S]</source>
        <translation>Uso: microsim-cli track --igtl HOST:PUERTO [--duration S] [--json ARCHIVO] [--record ARCHIVO] [--once] [--max-speed MM_S]</translation>
    </message>
    <message>
        <source>the file could not be read or written</source>
        <translation>no se pudo leer ni escribir el archivo</translation>
    </message>
    <message>
        <source>%1: [%2/%3] %4 (%5 s)</source>
        <translation>%1: [%2/%3] %4 (%5 s)</translation>
    </message>
    <message>
        <source>this build has no benchmarks (configure with -DMICROSIM_BUILD_BENCHMARKS=ON)</source>
        <translation>esta compilación no incluye benchmarks (configure con -DMICROSIM_BUILD_BENCHMARKS=ON)</translation>
    </message>
    <message>
        <source>name one benchmark (see --list)</source>
        <translation>indique un solo benchmark (vea --list)</translation>
    </message>
    <message>
        <source>unknown benchmark '%1' (see --list)</source>
        <translation>benchmark desconocido «%1» (vea --list)</translation>
    </message>
    <message>
        <source>'%1' has no curves to plot</source>
        <translation>«%1» no tiene curvas que dibujar</translation>
    </message>
    <message>
        <source>cannot write the plot %1</source>
        <translation>no se puede escribir el gráfico %1</translation>
    </message>
    <message>
        <source>cannot read %1</source>
        <translation>no se puede leer %1</translation>
    </message>
    <message>
        <source>%1 is not a JSON object: %2</source>
        <translation>%1 no es un objeto JSON: %2</translation>
    </message>
    <message numerus="yes">
        <source>%1 was cut short (the recording stopped before its end); using its %n complete sample(s)</source>
        <translation><numerusform>%1 está incompleto (la grabación se detuvo antes de su final); se usa su %n muestra completa</numerusform><numerusform>%1 está incompleto (la grabación se detuvo antes de su final); se usan sus %n muestras completas</numerusform></translation>
    </message>
    <message>
        <source>say pivot or register, and give --input FILE</source>
        <translation>indique pivot o register, y --input ARCHIVO</translation>
    </message>
    <message>
        <source>warning: %1</source>
        <translation>aviso: %1</translation>
    </message>
    <message>
        <source>the file or name the action takes</source>
        <translation>el archivo o el nombre que espera la acción</translation>
    </message>
    <message>
        <source>name an action: %1</source>
        <translation>indique una acción: %1</translation>
    </message>
    <message>
        <source>unknown action '%1' (known: %2)</source>
        <translation>acción desconocida «%1» (conocidas: %2)</translation>
    </message>
    <message>
        <source>%1 needs a file or a name after it</source>
        <translation>%1 necesita a continuación un archivo o un nombre</translation>
    </message>
    <message>
        <source>add-instructor reads the password from stdin: give --password-stdin</source>
        <translation>add-instructor lee la contraseña de stdin: indique --password-stdin</translation>
    </message>
    <message>
        <source>export-csv needs --instructor NAME (password on stdin)</source>
        <translation>export-csv necesita --instructor NOMBRE (contraseña por stdin)</translation>
    </message>
    <message>
        <source>%1 exists already; it was left untouched. Choose another name for the backup, or move that file away first.</source>
        <translation>%1 ya existe; no se ha modificado. Elija otro nombre para la copia de seguridad o mueva antes ese archivo.</translation>
    </message>
    <message>
        <source>give the server as --igtl HOST:PORT</source>
        <translation>indique el servidor como --igtl HOST:PUERTO</translation>
    </message>
    <message>
        <source>--duration and --max-speed take positive numbers</source>
        <translation>--duration y --max-speed esperan números positivos</translation>
    </message>
    <message>
        <source>cannot write %1</source>
        <translation>no se puede escribir %1</translation>
    </message>
    <message>
        <source>could not connect to %1:%2: %3</source>
        <translation>no se pudo conectar a %1:%2: %3</translation>
    </message>
    <message>
        <source>the recording was made on the scene %1, which is not there, not beside the recording and not among the shipped scenes (looked at: %2); give --scene FILE</source>
        <translation>la grabación se hizo con la escena %1, que no está ahí, ni junto a la grabación, ni entre las escenas incluidas (buscada en: %2); indique --scene ARCHIVO</translation>
    </message>
    <message>
        <source>%1 has changed since the recording was made on it (%2): the replay may differ from the attempt</source>
        <translation>%1 ha cambiado desde que se hizo la grabación con ella (%2): la reproducción puede diferir del intento</translation>
    </message>
    <message>
        <source>The scene &lt;file&gt; to run (default with --input: the one the recording names).</source>
        <translation>La escena &lt;file&gt; que se ejecutará (por defecto con --input: la que indica la grabación).</translation>
    </message>
    <message>
        <source>Usage: microsim-cli run (--scene FILE [--input REC | --script NAME] | --input REC) [--record REC] [--frames N] [--json OUT]</source>
        <translation>Uso: microsim-cli run (--scene ARCHIVO [--input GRAB | --script NOMBRE] | --input GRAB) [--record GRAB] [--frames N] [--json SALIDA]</translation>
    </message>
    <message>
        <source>give --scene FILE, or --input REC to replay it on the scene it was recorded on</source>
        <translation>indique --scene ARCHIVO, o --input GRAB para reproducirla en la escena con la que se grabó</translation>
    </message>
    <message>
        <source>forceps closes on nothing: nothing lies between its jaws</source>
        <translation>la pinza se cierra en vacío: no hay nada entre sus ramas</translation>
    </message>
    <message>
        <source>scissors cut the thread, leaving a %1 mm end</source>
        <translation>las tijeras cortan el hilo y dejan un cabo de %1 mm</translation>
    </message>
    <message>
        <source>scissors cut the thread</source>
        <translation>las tijeras cortan el hilo</translation>
    </message>
    <message>
        <source>the needle keeps %1 mm of thread, too short to tie</source>
        <translation>a la aguja le quedan %1 mm de hilo, demasiado corto para anudar</translation>
    </message>
    <message>
        <source>no knot</source>
        <translation>ningún nudo</translation>
    </message>
    <message>
        <source>a single throw</source>
        <translation>una lazada simple</translation>
    </message>
    <message>
        <source>a square knot</source>
        <translation>un nudo llano</translation>
    </message>
    <message>
        <source>a granny knot</source>
        <translation>un nudo de la abuela</translation>
    </message>
    <message>
        <source>a surgeon's knot</source>
        <translation>un nudo de cirujano</translation>
    </message>
    <message>
        <source>a slip knot</source>
        <translation>un nudo corredizo</translation>
    </message>
    <message>
        <source>an unknown knot</source>
        <translation>un nudo desconocido</translation>
    </message>
    <message>
        <source>right-handed</source>
        <translation>a derechas</translation>
    </message>
    <message>
        <source>left-handed</source>
        <translation>a izquierdas</translation>
    </message>
    <message numerus="yes">
        <source>throw %1 formed: %2, %n wrap(s); the knot reads %3</source>
        <translation><numerusform>lazada %1 formada: %2, %n vuelta; el nudo es %3</numerusform><numerusform>lazada %1 formada: %2, %n vueltas; el nudo es %3</numerusform></translation>
    </message>
    <message numerus="yes">
        <source>%1 pulled tight: %n throw(s), tension %2 µN</source>
        <translation><numerusform>%1 apretado: %n lazada, tensión %2 µN</numerusform><numerusform>%1 apretado: %n lazadas, tensión %2 µN</numerusform></translation>
    </message>
    <message>
        <source>the knot slips: it ran %1 mm along the thread under %2 µN</source>
        <translation>el nudo se desliza: recorrió %1 mm a lo largo del hilo con %2 µN</translation>
    </message>
    <message numerus="yes">
        <source>the knot slips: %n throw(s) left, it reads %1</source>
        <translation><numerusform>el nudo se desliza: queda %n lazada, es %1</numerusform><numerusform>el nudo se desliza: quedan %n lazadas, es %1</numerusform></translation>
    </message>
    <message>
        <source>end product</source>
        <translation>resultado final</translation>
    </message>
    <message>
        <source>lapse index %1</source>
        <translation>índice de fallos %1</translation>
    </message>
    <message>
        <source>error</source>
        <translation>error</translation>
    </message>
    <message>
        <source>stitch</source>
        <translation>punto</translation>
    </message>
    <message>
        <source>pierce</source>
        <translation>paso</translation>
    </message>
    <message>
        <source>at (°)</source>
        <translation>en (°)</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>medido</translation>
    </message>
    <message>
        <source>limit</source>
        <translation>límite</translation>
    </message>
    <message>
        <source>the scene has no severed vessel</source>
        <translation>la escena no tiene ningún vaso seccionado</translation>
    </message>
    <message>
        <source>no stitch joins the two ends</source>
        <translation>ningún punto une los dos extremos</translation>
    </message>
    <message>
        <source>a stitch names a face the tissue does not have</source>
        <translation>un punto nombra una cara que el tejido no tiene</translation>
    </message>
    <message>
        <source>the pressurised wall did not settle</source>
        <translation>la pared presurizada no llegó al equilibrio</translation>
    </message>
    <message>
        <source>the pressurised wall could not be solved</source>
        <translation>la pared presurizada no se pudo resolver</translation>
    </message>
    <message>
        <source>leak test</source>
        <translation>prueba de estanqueidad</translation>
    </message>
    <message>
        <source>not done: %1</source>
        <translation>no realizada: %1</translation>
    </message>
    <message>
        <source>%1 mmHg: largest gap %2 mm at %3°, limit %4 mm</source>
        <translation>%1 mmHg: mayor separación %2 mm en %3°, límite %4 mm</translation>
    </message>
    <message>
        <source>leaks</source>
        <translation>hay fuga</translation>
    </message>
    <message>
        <source>holds</source>
        <translation>estanca</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>Micro-anastomosis training simulator</source>
        <translation>Simulador de entrenamiento en microanastomosis</translation>
    </message>
    <message>
        <source>Write a PNG of each main screen to &lt;dir&gt;, then quit.</source>
        <translation>Escribir un PNG de cada pantalla principal en &lt;dir&gt; y salir.</translation>
    </message>
    <message>
        <source>dir</source>
        <translation>directorio</translation>
    </message>
    <message>
        <source>Use the SQLite history file &lt;file&gt; instead of the default.</source>
        <translation>Usar el archivo de historial SQLite &lt;file&gt; en lugar del predeterminado.</translation>
    </message>
    <message>
        <source>file</source>
        <translation>archivo</translation>
    </message>
    <message>
        <source>cannot create %1</source>
        <translation>no se puede crear %1</translation>
    </message>
    <message>
        <source>Start as usual, quit once the main window is drawn; exit 1 if it was not, or a lesson or the history could not be read.</source>
        <translation>Iniciar como de costumbre y salir en cuanto se dibuje la ventana principal; código de salida 1 si no se dibujó o si no se pudo leer una lección o el historial.</translation>
    </message>
    <message>
        <source>the main window was not drawn within %1 s</source>
        <translation>la ventana principal no se dibujó en %1 s</translation>
    </message>
    <message>
        <source>no lesson files in %1</source>
        <translation>no hay archivos de lección en %1</translation>
    </message>
    <message numerus="yes">
        <source>%1 of %n lesson file(s) in %2 could be read</source>
        <translation><numerusform>se pudieron leer %1 de %n archivo de lección en %2</numerusform><numerusform>se pudieron leer %1 de %n archivos de lección en %2</numerusform></translation>
    </message>
    <message numerus="yes">
        <source>microsim started: %n lesson(s) from %1, history %2</source>
        <translation><numerusform>microsim iniciado: %n lección de %1, historial %2</numerusform><numerusform>microsim iniciado: %n lecciones de %1, historial %2</numerusform></translation>
    </message>
</context>
<context>
    <name>microsim::gui::AddPersonDialog</name>
    <message>
        <source>Add a trainee</source>
        <translation>Añadir un residente</translation>
    </message>
    <message>
        <source>Add an instructor</source>
        <translation>Añadir un instructor</translation>
    </message>
    <message>
        <source>Add</source>
        <translation>Añadir</translation>
    </message>
</context>
<context>
    <name>microsim::gui::AttemptDetailView</name>
    <message>
        <source>Metric</source>
        <translation>Métrica</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Valor</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>Objetivo</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Tolerancia</translation>
    </message>
    <message>
        <source>Weight</source>
        <translation>Peso</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>Puntos</translation>
    </message>
    <message>
        <source>Feedback</source>
        <translation>Comentario</translation>
    </message>
    <message>
        <source>Pierce</source>
        <translation>Paso</translation>
    </message>
    <message>
        <source>A note for this attempt…</source>
        <translation>Una nota sobre este intento…</translation>
    </message>
    <message>
        <source>Add note</source>
        <translation>Añadir nota</translation>
    </message>
    <message>
        <source>Metrics</source>
        <translation>Métricas</translation>
    </message>
    <message>
        <source>Pierces</source>
        <translation>Pasos</translation>
    </message>
    <message>
        <source>Annotations</source>
        <translation>Notas</translation>
    </message>
    <message>
        <source>Replay in 3D</source>
        <translation>Reproducir en 3D</translation>
    </message>
    <message>
        <source>Choose an attempt in a trainee's history.</source>
        <translation>Elija un intento en el historial de un residente.</translation>
    </message>
    <message>
        <source>%1 — %2, %3, %4</source>
        <translation>%1 — %2, %3, %4</translation>
    </message>
    <message>
        <source>Score %1 of 100 (%2); rubric %3 version %4</source>
        <translation>Puntuación %1 de 100 (%2); rúbrica %3 versión %4</translation>
    </message>
    <message>
        <source>passed</source>
        <translation>aprobado</translation>
    </message>
    <message>
        <source>not passed</source>
        <translation>no aprobado</translation>
    </message>
    <message>
        <source>No recording stored.</source>
        <translation>No hay grabación guardada.</translation>
    </message>
    <message>
        <source>The lesson's scene is not installed.</source>
        <translation>La escena de la lección no está instalada.</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>sí</translation>
    </message>
    <message>
        <source>no</source>
        <translation>no</translation>
    </message>
    <message>
        <source>%1, %2:
%3</source>
        <translation>%1, %2:
%3</translation>
    </message>
    <message numerus="yes">
        <source>Replay finished: %n frame(s).</source>
        <translation><numerusform>Reproducción terminada: %n fotograma.</numerusform><numerusform>Reproducción terminada: %n fotogramas.</numerusform></translation>
    </message>
    <message>
        <source>The stored recording is damaged.</source>
        <translation>La grabación guardada está dañada.</translation>
    </message>
    <message>
        <source>The lesson's scene could not be loaded.</source>
        <translation>No se pudo cargar la escena de la lección.</translation>
    </message>
    <message numerus="yes">
        <source>Replaying %n frame(s)…</source>
        <translation><numerusform>Reproduciendo %n fotograma…</numerusform><numerusform>Reproduciendo %n fotogramas…</numerusform></translation>
    </message>
    <message>
        <source>Paused.</source>
        <translation>En pausa.</translation>
    </message>
    <message>
        <source>End product</source>
        <translation>Resultado final</translation>
    </message>
</context>
<context>
    <name>microsim::gui::AttemptPage</name>
    <message>
        <source>Finish attempt</source>
        <translation>Terminar el intento</translation>
    </message>
    <message>
        <source>Abandon</source>
        <translation>Abandonar</translation>
    </message>
    <message>
        <source>The rubric %1 cannot be read (field %2, line %3).</source>
        <translation>No se puede leer la rúbrica %1 (campo %2, línea %3).</translation>
    </message>
    <message>
        <source>The scene %1 cannot be loaded (field %2, line %3).</source>
        <translation>No se puede cargar la escena %1 (campo %2, línea %3).</translation>
    </message>
    <message>
        <source>Learn mode: each step is ticked off as you do it.</source>
        <translation>Modo aprendizaje: cada paso se marca en cuanto lo realiza.</translation>
    </message>
    <message>
        <source>Learn mode: follow the marks.</source>
        <translation>Modo aprendizaje: siga las marcas.</translation>
    </message>
    <message>
        <source>Test mode: graded, no hints.</source>
        <translation>Modo examen: calificado, sin ayudas.</translation>
    </message>
    <message>
        <source>This attempt is not stored (no history).</source>
        <translation>Este intento no se guarda (sin historial).</translation>
    </message>
    <message>
        <source>Replaying a recording…</source>
        <translation>Reproduciendo una grabación…</translation>
    </message>
    <message>
        <source>Every step is done: finish the attempt when you are ready.</source>
        <translation>Todos los pasos están hechos: termine el intento cuando esté listo.</translation>
    </message>
    <message>
        <source>Scoring…</source>
        <translation>Calificando…</translation>
    </message>
    <message>
        <source>The recording %1 could not be replayed for scoring.</source>
        <translation>No se pudo reproducir la grabación %1 para calificarla.</translation>
    </message>
    <message>
        <source>The score could not be stored (%1).</source>
        <translation>No se pudo guardar la puntuación (%1).</translation>
    </message>
    <message>
        <source>Abandon the attempt?</source>
        <translation>¿Abandonar el intento?</translation>
    </message>
    <message>
        <source>The attempt ends here without a score. It stays in your history as abandoned.</source>
        <translation>El intento termina aquí sin calificación. Queda en su historial como abandonado.</translation>
    </message>
    <message>
        <source>Keep practising</source>
        <translation>Seguir practicando</translation>
    </message>
    <message>
        <source>The tissue solver %1 chosen in the settings is not known; choose another.</source>
        <translation>El solucionador de tejido %1 elegido en los ajustes no se conoce; elija otro.</translation>
    </message>
    <message>
        <source>This attempt is not stored: the history refused it (%1).</source>
        <translation>Este intento no se guarda: el historial lo rechazó (%1).</translation>
    </message>
    <message>
        <source>The history could not mark the attempt abandoned (%1).</source>
        <translation>El historial no pudo marcar el intento como abandonado (%1).</translation>
    </message>
    <message>
        <source>The left forceps closed on nothing: nothing lay between its jaws.</source>
        <translation>La pinza izquierda se cerró en vacío: no había nada entre sus ramas.</translation>
    </message>
    <message>
        <source>The right forceps closed on nothing: nothing lay between its jaws.</source>
        <translation>La pinza derecha se cerró en vacío: no había nada entre sus ramas.</translation>
    </message>
    <message>
        <source>The scissors cut the thread: the cut end is %1 long.</source>
        <translation>Las tijeras cortaron el hilo: el cabo cortado mide %1.</translation>
    </message>
    <message>
        <source>The scissors cut the thread: no stitch holds it on either side of the cut.</source>
        <translation>Las tijeras cortaron el hilo: ningún punto lo sujeta a ningún lado del corte.</translation>
    </message>
    <message>
        <source>Too short to tie: the needle keeps only %1 of thread.</source>
        <translation>Demasiado corto para anudar: a la aguja solo le quedan %1 de hilo.</translation>
    </message>
</context>
<context>
    <name>microsim::gui::CalibrationSession</name>
    <message>
        <source>Cannot read %1.</source>
        <translation>No se puede leer %1.</translation>
    </message>
    <message>
        <source>%1 is neither a recording nor a tracker stream.</source>
        <translation>%1 no es ni una grabación ni un flujo del rastreador.</translation>
    </message>
    <message>
        <source>%1 is damaged.</source>
        <translation>%1 está dañado.</translation>
    </message>
    <message>
        <source>Save setup profile</source>
        <translation>Guardar perfil de configuración</translation>
    </message>
    <message>
        <source>The database is not open.</source>
        <translation>La base de datos no está abierta.</translation>
    </message>
    <message>
        <source>Profile name:</source>
        <translation>Nombre del perfil:</translation>
    </message>
    <message>
        <source>Calibrated by:</source>
        <translation>Calibrado por:</translation>
    </message>
    <message>
        <source>The profile could not be stored: %1</source>
        <translation>No se pudo guardar el perfil: %1</translation>
    </message>
    <message>
        <source>&amp;Calibration</source>
        <translation>&amp;Calibración</translation>
    </message>
    <message>
        <source>Calibration</source>
        <translation>Calibración</translation>
    </message>
    <message>
        <source>Connect a tracker or open a tracker recording first.</source>
        <translation>Conecte primero un rastreador o abra una grabación del rastreador.</translation>
    </message>
    <message>
        <source>Connect to OpenIGTLink…</source>
        <translation>Conectar a OpenIGTLink…</translation>
    </message>
    <message>
        <source>Connect to OpenIGTLink</source>
        <translation>Conectar a OpenIGTLink</translation>
    </message>
    <message>
        <source>Server (host:port):</source>
        <translation>Servidor (host:puerto):</translation>
    </message>
    <message>
        <source>Give the server as host:port.</source>
        <translation>Indique el servidor como host:puerto.</translation>
    </message>
    <message>
        <source>Play a tracker recording…</source>
        <translation>Reproducir una grabación del rastreador…</translation>
    </message>
    <message>
        <source>Play a tracker recording</source>
        <translation>Reproducir una grabación del rastreador</translation>
    </message>
    <message>
        <source>Recordings (*.json *.msrec)</source>
        <translation>Grabaciones (*.json *.msrec)</translation>
    </message>
    <message>
        <source>Setup profile…</source>
        <translation>Perfil de configuración…</translation>
    </message>
    <message>
        <source>Save setup profile…</source>
        <translation>Guardar perfil de configuración…</translation>
    </message>
    <message>
        <source>Pivot calibration…</source>
        <translation>Calibración por pivote…</translation>
    </message>
    <message>
        <source>Registration…</source>
        <translation>Registro…</translation>
    </message>
    <message>
        <source>Forceps closure…</source>
        <translation>Cierre de la pinza…</translation>
    </message>
    <message>
        <source>Left hand</source>
        <translation>Mano izquierda</translation>
    </message>
    <message>
        <source>Right hand</source>
        <translation>Mano derecha</translation>
    </message>
    <message>
        <source>Forceps closure</source>
        <translation>Cierre de la pinza</translation>
    </message>
    <message>
        <source>Hand:</source>
        <translation>Mano:</translation>
    </message>
    <message>
        <source>Motion scaling…</source>
        <translation>Escalado del movimiento…</translation>
    </message>
    <message>
        <source>Latency…</source>
        <translation>Latencia…</translation>
    </message>
    <message>
        <source>Live view of the tools</source>
        <translation>Vista en vivo de los instrumentos</translation>
    </message>
    <message>
        <source>Calibrated tools</source>
        <translation>Instrumentos calibrados</translation>
    </message>
    <message>
        <source>Use a 3D mouse (spacenavd)</source>
        <translation>Usar un ratón 3D (spacenavd)</translation>
    </message>
    <message>
        <source>3D mouse</source>
        <translation>Ratón 3D</translation>
    </message>
    <message>
        <source>3D mouse connected: push or turn the cap to move the active forceps; the left button closes the jaws, the right one switches the hand.</source>
        <translation>Ratón 3D conectado: empuje o gire la tapa para mover la pinza activa; el botón izquierdo cierra las ramas, el derecho cambia de mano.</translation>
    </message>
    <message>
        <source>Use a game controller</source>
        <translation>Usar un mando de juego</translation>
    </message>
    <message>
        <source>Game controller</source>
        <translation>Mando de juego</translation>
    </message>
    <message>
        <source>%1 connected: sticks move the active forceps, the triggers close the jaws, the shoulder buttons choose the hand.</source>
        <translation>%1 conectado: las palancas mueven la pinza activa, los gatillos cierran las ramas, los botones superiores eligen la mano.</translation>
    </message>
</context>
<context>
    <name>microsim::gui::ClosureDialog</name>
    <message>
        <source>Forceps closure</source>
        <translation>Cierre de la pinza</translation>
    </message>
    <message>
        <source>Open the jaws fully, then squeeze them shut a few times.</source>
        <translation>Abra las mandíbulas del todo y luego ciérrelas apretando varias veces.</translation>
    </message>
    <message>
        <source>Start again</source>
        <translation>Empezar de nuevo</translation>
    </message>
    <message>
        <source>Channel:</source>
        <translation>Canal:</translation>
    </message>
    <message>
        <source>No reading yet.</source>
        <translation>Aún no hay lecturas.</translation>
    </message>
    <message numerus="yes">
        <source>Open %1 · closed %2 (%n reading(s))</source>
        <translation><numerusform>Abierta %1 · cerrada %2 (%n lectura)</numerusform><numerusform>Abierta %1 · cerrada %2 (%n lecturas)</numerusform></translation>
    </message>
</context>
<context>
    <name>microsim::gui::EndProductPanel</name>
    <message>
        <source>&lt;b&gt;Opened vessel&lt;/b&gt;: cut along its axis and laid flat; 0° faces the microscope. Dots are passages, blue lines the stitches' thread, numbered marks the errors.</source>
        <translation>&lt;b&gt;Vaso abierto&lt;/b&gt;: cortado a lo largo de su eje y extendido; 0° mira al microscopio. Los puntos son pasos por la pared, las líneas azules el hilo de los puntos de sutura, las marcas numeradas los errores.</translation>
    </message>
    <message>
        <source>#</source>
        <translation>N.º</translation>
    </message>
    <message>
        <source>Error</source>
        <translation>Error</translation>
    </message>
    <message>
        <source>Where</source>
        <translation>Dónde</translation>
    </message>
    <message>
        <source>Measured</source>
        <translation>Medido</translation>
    </message>
    <message>
        <source>The end product was not judged: this attempt was scored before its errors were kept.</source>
        <translation>El resultado final no se evaluó: este intento se calificó antes de que se guardaran sus errores.</translation>
    </message>
    <message>
        <source>No end-product errors.</source>
        <translation>Sin errores en el resultado final.</translation>
    </message>
    <message>
        <source>stitch %1</source>
        <translation>punto %1</translation>
    </message>
    <message>
        <source>pierce %1</source>
        <translation>paso %1</translation>
    </message>
    <message>
        <source>at %1°</source>
        <comment>an angle round the vessel</comment>
        <translation>a %1°</translation>
    </message>
    <message>
        <source>not located</source>
        <translation>sin ubicar</translation>
    </message>
    <message>
        <source>%1 wall thicknesses</source>
        <translation>%1 grosores de pared</translation>
    </message>
    <message>
        <source>bites %1 apart</source>
        <translation>pasos separados %1</translation>
    </message>
    <message>
        <source>gap %1 off the mean</source>
        <translation>separación %1 fuera de la media</translation>
    </message>
    <message>
        <source>%1 (limit %2)</source>
        <translation>%1 (límite %2)</translation>
    </message>
    <message>
        <source>End-product errors (Anastomosis Lapse Index): %1</source>
        <translation>Errores del resultado final (Anastomosis Lapse Index): %1</translation>
    </message>
    <message>
        <source>links torn: %1</source>
        <translation>enlaces rotos: %1</translation>
    </message>
    <message>
        <source>bites squeezed by %1</source>
        <translation>pasos comprimidos un %1</translation>
    </message>
    <message>
        <source>%1 into the lumen</source>
        <translation>%1 dentro de la luz</translation>
    </message>
    <message>
        <source>edges past each other, %1 out of line</source>
        <translation>bordes superpuestos, desalineados %1</translation>
    </message>
</context>
<context>
    <name>microsim::gui::FeedbackText</name>
    <message>
        <source>Take the same bite on both ends.</source>
        <translation>Tome la misma distancia en ambos extremos.</translation>
    </message>
    <message>
        <source>Pass through the whole wall, not only part of it.</source>
        <translation>Atraviese toda la pared, no solo una parte.</translation>
    </message>
    <message>
        <source>Enter closer to the cut edge.</source>
        <translation>Entre más cerca del borde cortado.</translation>
    </message>
    <message>
        <source>Enter further from the cut edge: the stitch may tear out.</source>
        <translation>Entre más lejos del borde cortado: el punto puede desgarrarse.</translation>
    </message>
    <message>
        <source>Enter the wall more perpendicularly.</source>
        <translation>Entre en la pared de forma más perpendicular.</translation>
    </message>
    <message>
        <source>Follow the needle's curve so it leaves the wall perpendicularly.</source>
        <translation>Siga la curva de la aguja para que salga perpendicular a la pared.</translation>
    </message>
    <message>
        <source>Re-grasp less: plan each grip.</source>
        <translation>Reagarre menos: planifique cada agarre.</translation>
    </message>
    <message>
        <source>Fewer pauses: keep the movement going.</source>
        <translation>Menos pausas: mantenga el movimiento.</translation>
    </message>
    <message>
        <source>Move more smoothly.</source>
        <translation>Muévase con más suavidad.</translation>
    </message>
    <message>
        <source>Shorter, more direct instrument paths.</source>
        <translation>Recorridos del instrumento más cortos y directos.</translation>
    </message>
    <message>
        <source>The back wall was caught: this closes the vessel.</source>
        <translation>Se atrapó la pared posterior: esto cierra el vaso.</translation>
    </message>
    <message>
        <source>The suture broke: pull more gently.</source>
        <translation>La sutura se rompió: tire con más suavidad.</translation>
    </message>
    <message>
        <source>The tissue was torn or over-stretched.</source>
        <translation>El tejido se desgarró o se estiró demasiado.</translation>
    </message>
    <message>
        <source>The needle did not pass through the wall.</source>
        <translation>La aguja no atravesó la pared.</translation>
    </message>
    <message>
        <source>The stitch was not completed through both ends.</source>
        <translation>El punto no se completó a través de ambos extremos.</translation>
    </message>
    <message>
        <source>Too few stitches.</source>
        <translation>Muy pocos puntos.</translation>
    </message>
    <message>
        <source>More stitches than needed.</source>
        <translation>Más puntos de los necesarios.</translation>
    </message>
    <message>
        <source>Counts only once part of the task is done.</source>
        <translation>Solo cuenta cuando se ha hecho parte de la tarea.</translation>
    </message>
    <message>
        <source>Work faster.</source>
        <translation>Trabaje más rápido.</translation>
    </message>
    <message>
        <source>Handle the tissue more gently: it was over-stretched.</source>
        <translation>Manipule el tejido con más suavidad: se estiró demasiado.</translation>
    </message>
    <message>
        <source>Space the first three stitches 120° apart.</source>
        <translation>Separe los tres primeros puntos 120°.</translation>
    </message>
    <message>
        <source>%1: not measured in this attempt.</source>
        <translation>%1: no medido en este intento.</translation>
    </message>
    <message>
        <source>%1 is too high.</source>
        <translation>%1 es demasiado alto.</translation>
    </message>
    <message>
        <source>%1 is too low.</source>
        <translation>%1 es demasiado bajo.</translation>
    </message>
    <message>
        <source>Pass each wall once: every extra passage injures it.</source>
        <translation>Atraviese cada pared una sola vez: cada paso de más la lesiona.</translation>
    </message>
    <message>
        <source>Turn the needle along its curve instead of pushing it.</source>
        <translation>Gire la aguja siguiendo su curva en lugar de empujarla.</translation>
    </message>
    <message>
        <source>The needle was dragged sideways through the tissue, not turned along its curve.</source>
        <translation>La aguja se arrastró de lado por el tejido en lugar de girarla siguiendo su curva.</translation>
    </message>
    <message>
        <source>%1: not applicable to this input; not counted.</source>
        <translation>%1: no aplicable a esta entrada; no se cuenta.</translation>
    </message>
    <message>
        <source>Cut both tails of every knot with the microscissors (T).</source>
        <translation>Corte ambos cabos de cada nudo con las microtijeras (T).</translation>
    </message>
    <message>
        <source>Cut the tails shorter: about 1 mm from the knot.</source>
        <translation>Corte los cabos más cortos: a aproximadamente 1 mm del nudo.</translation>
    </message>
    <message>
        <source>Leave longer tails, about 1 mm: a tail cut at the knot lets it untie.</source>
        <translation>Deje cabos más largos, de aproximadamente 1 mm: un cabo cortado al ras del nudo permite que se suelte.</translation>
    </message>
    <message>
        <source>The finished anastomosis has errors: see the list of lapses.</source>
        <translation>La anastomosis terminada tiene errores: vea la lista de fallos.</translation>
    </message>
    <message>
        <source>Tie a square or surgeon's knot: a double throw, then a single throw the other way.</source>
        <translation>Haga un nudo cuadrado o de cirujano: una vuelta doble y luego una simple en sentido contrario.</translation>
    </message>
    <message>
        <source>Tie every stitch: wrap the thread round the forceps, grasp the tail, pull it through.</source>
        <translation>Anude cada punto: enrolle el hilo alrededor de la pinza, tome el cabo corto y tire de él.</translation>
    </message>
    <message>
        <source>Lay at least two throws, the second the other way round.</source>
        <translation>Haga al menos dos vueltas, la segunda en sentido contrario.</translation>
    </message>
    <message>
        <source>A knot slipped: the stitch would open. Alternate the throws and snug each one down.</source>
        <translation>Un nudo se deslizó: el punto se abriría. Alterne las vueltas y apriete cada una.</translation>
    </message>
    <message>
        <source>The suture line leaks under pressure: close the widest gap with another stitch.</source>
        <translation>La línea de sutura tiene fuga bajo presión: cierre la mayor separación con otro punto.</translation>
    </message>
</context>
<context>
    <name>microsim::gui::LatencyDialog</name>
    <message>
        <source>Latency</source>
        <translation>Latencia</translation>
    </message>
    <message>
        <source>Hold the tool and the reference together and move them briskly in every direction for about ten seconds.</source>
        <translation>Sujete juntos el instrumento y la referencia y muévalos con rapidez en todas las direcciones durante unos diez segundos.</translation>
    </message>
    <message>
        <source>Record</source>
        <translation>Grabar</translation>
    </message>
    <message>
        <source>Tracked device:</source>
        <translation>Dispositivo rastreado:</translation>
    </message>
    <message>
        <source>Reference device:</source>
        <translation>Dispositivo de referencia:</translation>
    </message>
    <message>
        <source>Stop and estimate</source>
        <translation>Detener y estimar</translation>
    </message>
    <message>
        <source>Recording…</source>
        <translation>Grabando…</translation>
    </message>
    <message>
        <source>Latency %1 ms (correlation %2)</source>
        <translation>Latencia %1 ms (correlación %2)</translation>
    </message>
    <message>
        <source>Too short: record longer.</source>
        <translation>Demasiado corto: grabe más tiempo.</translation>
    </message>
    <message>
        <source>The devices sent invalid samples.</source>
        <translation>Los dispositivos enviaron muestras no válidas.</translation>
    </message>
    <message>
        <source>No motion: move the tool.</source>
        <translation>Sin movimiento: mueva el instrumento.</translation>
    </message>
    <message>
        <source>The motions do not match (correlation %1): move them together.</source>
        <translation>Los movimientos no coinciden (correlación %1): muévalos juntos.</translation>
    </message>
</context>
<context>
    <name>microsim::gui::LessonListPage</name>
    <message>
        <source>Lesson</source>
        <translation>Lección</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Estado</translation>
    </message>
    <message>
        <source>Learn (guided)</source>
        <translation>Aprender (guiado)</translation>
    </message>
    <message>
        <source>Test (graded)</source>
        <translation>Examen (calificado)</translation>
    </message>
    <message>
        <source>Sign out</source>
        <translation>Salir</translation>
    </message>
    <message>
        <source>&lt;h2&gt;Lessons for %1&lt;/h2&gt;</source>
        <translation>&lt;h2&gt;Lecciones de %1&lt;/h2&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;Goals&lt;/b&gt;&lt;ul&gt;</source>
        <translation>&lt;b&gt;Objetivos&lt;/b&gt;&lt;ul&gt;</translation>
    </message>
    <message>
        <source>My progress</source>
        <translation>Mi progreso</translation>
    </message>
    <message>
        <source>Your scores over your attempts, each attempt's feedback and your instructors' notes</source>
        <translation>Sus puntuaciones a lo largo de sus intentos, la retroalimentación de cada intento y las notas de sus instructores</translation>
    </message>
    <message>
        <source>The history could not be read: %1</source>
        <translation>No se pudo leer el historial: %1</translation>
    </message>
</context>
<context>
    <name>microsim::gui::LessonStatusText</name>
    <message>
        <source>not started</source>
        <translation>sin empezar</translation>
    </message>
    <message>
        <source>practised</source>
        <translation>practicada</translation>
    </message>
    <message>
        <source>passed</source>
        <translation>aprobada</translation>
    </message>
    <message>
        <source>proficient</source>
        <translation>dominada</translation>
    </message>
</context>
<context>
    <name>microsim::gui::LiveToolView</name>
    <message>
        <source>top (x–y)</source>
        <translation>arriba (x–y)</translation>
    </message>
    <message>
        <source>side (x–z)</source>
        <translation>lateral (x–z)</translation>
    </message>
</context>
<context>
    <name>microsim::gui::MainWindow</name>
    <message>
        <source>microsim — micro-anastomosis trainer</source>
        <translation>microsim — entrenador de microanastomosis</translation>
    </message>
    <message>
        <source>History: %1 (schema %2)</source>
        <translation>Historial: %1 (esquema %2)</translation>
    </message>
    <message>
        <source>History unavailable: cannot create the folder for %1</source>
        <translation>Historial no disponible: no se puede crear la carpeta de %1</translation>
    </message>
    <message>
        <source>History unavailable: cannot open %1</source>
        <translation>Historial no disponible: no se puede abrir %1</translation>
    </message>
    <message>
        <source>History unavailable: %1 is not a microsim database or is damaged; it was left untouched</source>
        <translation>Historial no disponible: %1 no es una base de datos de microsim o está dañada; no se ha modificado</translation>
    </message>
    <message>
        <source>History unavailable: %1 is locked by another program</source>
        <translation>Historial no disponible: otro programa tiene bloqueado %1</translation>
    </message>
    <message>
        <source>History unavailable: %1 was written by a newer microsim</source>
        <translation>Historial no disponible: %1 fue escrito por una versión más reciente de microsim</translation>
    </message>
    <message>
        <source>History unavailable: updating %1 failed; it was left as it was</source>
        <translation>Historial no disponible: la actualización de %1 falló; quedó como estaba</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Archivo</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Salir</translation>
    </message>
    <message>
        <source>&amp;Settings</source>
        <translation>&amp;Configuración</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>Ay&amp;uda</translation>
    </message>
    <message>
        <source>&amp;About microsim</source>
        <translation>&amp;Acerca de microsim</translation>
    </message>
    <message>
        <source>The language changes at the next start.</source>
        <translation>El idioma cambiará en el próximo inicio.</translation>
    </message>
    <message>
        <source>About microsim</source>
        <translation>Acerca de microsim</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;microsim %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Practise and assessment of microvascular anastomosis under a virtual operating microscope.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;microsim %1&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Práctica y evaluación de anastomosis microvasculares bajo un microscopio quirúrgico virtual.&lt;/p&gt;</translation>
    </message>
    <message numerus="yes">
        <source>%n lesson file(s) could not be read; the first: %1 (%2)</source>
        <translation><numerusform>No se pudo leer %n archivo de lección; el primero: %1 (%2)</numerusform><numerusform>No se pudieron leer %n archivos de lección; el primero: %1 (%2)</numerusform></translation>
    </message>
    <message>
        <source>Instructor: %1</source>
        <translation>Instructor: %1</translation>
    </message>
    <message>
        <source>Trainee: %1</source>
        <translation>Residente: %1</translation>
    </message>
    <message>
        <source>History unavailable: %1 is read-only; it was left untouched</source>
        <translation>Historial no disponible: %1 es de solo lectura; no se ha modificado</translation>
    </message>
    <message>
        <source>&amp;Replay a recording into this attempt…</source>
        <translation>&amp;Reproducir una grabación en este intento…</translation>
    </message>
    <message>
        <source>&amp;Preferences…</source>
        <translation>&amp;Preferencias…</translation>
    </message>
    <message>
        <source>The lesson cannot start</source>
        <translation>La lección no puede empezar</translation>
    </message>
    <message>
        <source>Start a lesson first; the recording is then replayed into it.</source>
        <translation>Empiece primero una lección; la grabación se reproducirá en ella.</translation>
    </message>
    <message>
        <source>Replay a recording</source>
        <translation>Reproducir una grabación</translation>
    </message>
    <message>
        <source>Recordings (*.msrec)</source>
        <translation>Grabaciones (*.msrec)</translation>
    </message>
    <message>
        <source>%1 is not a readable recording.</source>
        <translation>%1 no es una grabación legible.</translation>
    </message>
    <message>
        <source>Settings saved; the solver applies from the next attempt.</source>
        <translation>Ajustes guardados; el resolutor se aplica desde el próximo intento.</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ver</translation>
    </message>
    <message>
        <source>&amp;Microscope view (reset)</source>
        <translation>Vista del &amp;microscopio (restablecer)</translation>
    </message>
    <message>
        <source>&amp;Top view</source>
        <translation>Vista &amp;superior</translation>
    </message>
    <message>
        <source>&amp;Oblique view</source>
        <translation>Vista &amp;oblicua</translation>
    </message>
    <message>
        <source>&amp;Side view</source>
        <translation>Vista &amp;lateral</translation>
    </message>
    <message>
        <source>&amp;Keys and mouse</source>
        <translation>&amp;Teclas y ratón</translation>
    </message>
    <message>
        <source>&amp;People</source>
        <translation>&amp;Personas</translation>
    </message>
    <message>
        <source>Add a &amp;trainee…</source>
        <translation>Añadir un &amp;residente…</translation>
    </message>
    <message>
        <source>Add an &amp;instructor…</source>
        <translation>Añadir un &amp;instructor…</translation>
    </message>
    <message>
        <source>Trainee %1 added.</source>
        <translation>Residente %1 añadido.</translation>
    </message>
    <message>
        <source>Instructor %1 added.</source>
        <translation>Instructor %1 añadido.</translation>
    </message>
    <message>
        <source>&amp;Depth of field</source>
        <translation>&amp;Profundidad de campo</translation>
    </message>
    <message>
        <source>Blur what lies above or below the focal plane, as a microscope does</source>
        <translation>Desenfocar lo que queda por encima o por debajo del plano focal, como hace un microscopio</translation>
    </message>
</context>
<context>
    <name>microsim::gui::MetricVocabulary</name>
    <message>
        <source>Time</source>
        <translation>Tiempo</translation>
    </message>
    <message>
        <source>Path length</source>
        <translation>Recorrido</translation>
    </message>
    <message>
        <source>Path length, left hand</source>
        <translation>Recorrido, mano izquierda</translation>
    </message>
    <message>
        <source>Path length, right hand</source>
        <translation>Recorrido, mano derecha</translation>
    </message>
    <message>
        <source>Movements</source>
        <translation>Movimientos</translation>
    </message>
    <message>
        <source>Smoothness</source>
        <translation>Suavidad</translation>
    </message>
    <message>
        <source>Idle time</source>
        <translation>Tiempo inactivo</translation>
    </message>
    <message>
        <source>Re-grasps</source>
        <translation>Reagarres</translation>
    </message>
    <message>
        <source>Suture breaks</source>
        <translation>Roturas del hilo</translation>
    </message>
    <message>
        <source>Largest tissue stretch</source>
        <translation>Mayor estiramiento del tejido</translation>
    </message>
    <message>
        <source>Tissue damage</source>
        <translation>Daño tisular</translation>
    </message>
    <message>
        <source>Wall passages</source>
        <translation>Pasos por la pared</translation>
    </message>
    <message>
        <source>Needle off its arc</source>
        <translation>Aguja fuera de su arco</translation>
    </message>
    <message>
        <source>Entry angle</source>
        <translation>Ángulo de entrada</translation>
    </message>
    <message>
        <source>Exit angle</source>
        <translation>Ángulo de salida</translation>
    </message>
    <message>
        <source>Bite</source>
        <translation>Distancia al borde</translation>
    </message>
    <message>
        <source>Bite in wall thicknesses</source>
        <translation>Distancia del punto en grosores de pared</translation>
    </message>
    <message>
        <source>Full-thickness passages</source>
        <translation>Pasos de espesor completo</translation>
    </message>
    <message>
        <source>Back-wall catches</source>
        <translation>Pared posterior atrapada</translation>
    </message>
    <message>
        <source>Stitches</source>
        <translation>Puntos</translation>
    </message>
    <message>
        <source>Bite asymmetry</source>
        <translation>Asimetría de los pasos</translation>
    </message>
    <message>
        <source>Stitch spacing</source>
        <translation>Separación de los puntos</translation>
    </message>
    <message>
        <source>Triangulation error</source>
        <translation>Error de triangulación</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Posición en la circunferencia</translation>
    </message>
    <message>
        <source>Full thickness</source>
        <translation>Espesor completo</translation>
    </message>
    <message>
        <source>Back wall</source>
        <translation>Pared posterior</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <comment>a label and its unit</comment>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Anastomosis lapse index</source>
        <translation>Índice de fallos de la anastomosis</translation>
    </message>
    <message>
        <source>Oblique stitches</source>
        <translation>Puntos oblicuos</translation>
    </message>
    <message>
        <source>Partial-thickness bites</source>
        <translation>Pasos de espesor parcial</translation>
    </message>
    <message>
        <source>Wide bites</source>
        <translation>Pasos demasiado anchos</translation>
    </message>
    <message>
        <source>Unequally spaced stitches</source>
        <translation>Puntos con separación desigual</translation>
    </message>
    <message>
        <source>Knots tied</source>
        <translation>Nudos anudados</translation>
    </message>
    <message>
        <source>Secure knots</source>
        <translation>Nudos seguros</translation>
    </message>
    <message>
        <source>Knots slipped</source>
        <translation>Nudos deslizados</translation>
    </message>
    <message>
        <source>Throws per knot</source>
        <translation>Vueltas por nudo</translation>
    </message>
    <message>
        <source>Tails cut</source>
        <translation>Cabos cortados</translation>
    </message>
    <message>
        <source>Cut-end length</source>
        <translation>Longitud de los cabos</translation>
    </message>
    <message>
        <source>Leaks under pressure</source>
        <translation>Fuga bajo presión</translation>
    </message>
    <message>
        <source>Largest gap under pressure</source>
        <translation>Mayor separación bajo presión</translation>
    </message>
</context>
<context>
    <name>microsim::gui::MotionScalingDialog</name>
    <message>
        <source>Motion scaling</source>
        <translation>Escalado del movimiento</translation>
    </message>
    <message>
        <source> mm per mm</source>
        <translation> mm por mm</translation>
    </message>
    <message>
        <source> mm</source>
        <translation> mm</translation>
    </message>
    <message>
        <source>Hand motion per scene motion:</source>
        <translation>Movimiento de la mano por movimiento en la escena:</translation>
    </message>
    <message>
        <source>Fixed scene point (x, y, z):</source>
        <translation>Punto fijo de la escena (x, y, z):</translation>
    </message>
</context>
<context>
    <name>microsim::gui::MyProgressPage</name>
    <message>
        <source>&lt;h2&gt;My progress&lt;/h2&gt;</source>
        <translation>&lt;h2&gt;Mi progreso&lt;/h2&gt;</translation>
    </message>
    <message>
        <source>Back to the lessons</source>
        <translation>Volver a las lecciones</translation>
    </message>
    <message>
        <source>Lesson:</source>
        <translation>Lección:</translation>
    </message>
    <message>
        <source>Scores</source>
        <translation>Puntuaciones</translation>
    </message>
    <message>
        <source>Attempt</source>
        <translation>Intento</translation>
    </message>
    <message>
        <source>Reading your history…</source>
        <translation>Leyendo su historial…</translation>
    </message>
    <message>
        <source>Your history could not be read (%1).</source>
        <translation>No se pudo leer su historial (%1).</translation>
    </message>
    <message numerus="yes">
        <source>%n of these attempts carry an instructor's note: choose one to read it.</source>
        <translation><numerusform>%n de estos intentos tiene una nota de un instructor: elíjalo para leerla.</numerusform><numerusform>%n de estos intentos tienen una nota de un instructor: elija uno para leerla.</numerusform></translation>
    </message>
</context>
<context>
    <name>microsim::gui::NewPersonForm</name>
    <message>
        <source>Name</source>
        <translation>Nombre</translation>
    </message>
    <message>
        <source>none</source>
        <translation>ninguno</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>Grupo</translation>
    </message>
    <message numerus="yes">
        <source>at least %n characters</source>
        <translation><numerusform>al menos %n carácter</numerusform><numerusform>al menos %n caracteres</numerusform></translation>
    </message>
    <message>
        <source>Password</source>
        <translation>Contraseña</translation>
    </message>
    <message>
        <source>Password again</source>
        <translation>Repetir contraseña</translation>
    </message>
    <message>
        <source>Type a name first.</source>
        <translation>Escriba primero un nombre.</translation>
    </message>
    <message numerus="yes">
        <source>The password needs at least %n characters.</source>
        <translation><numerusform>La contraseña necesita al menos %n carácter.</numerusform><numerusform>La contraseña necesita al menos %n caracteres.</numerusform></translation>
    </message>
    <message>
        <source>The two passwords differ; type them again.</source>
        <translation>Las dos contraseñas no coinciden; escríbalas de nuevo.</translation>
    </message>
    <message>
        <source>A person called %1 already exists.</source>
        <translation>Ya existe una persona llamada %1.</translation>
    </message>
    <message>
        <source>An instructor has been set up meanwhile; sign in as them.</source>
        <translation>Mientras tanto se ha creado un instructor; inicie sesión como él.</translation>
    </message>
    <message>
        <source>%1 could not be added (%2).</source>
        <translation>No se pudo añadir a %1 (%2).</translation>
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
        <translation>Sin ubicar: %1</translation>
    </message>
    <message>
        <source>end 1</source>
        <translation>extremo 1</translation>
    </message>
    <message>
        <source>end 2</source>
        <translation>extremo 2</translation>
    </message>
    <message>
        <source>%1°</source>
        <comment>an angle round the vessel</comment>
        <translation>%1°</translation>
    </message>
    <message>
        <source>front wall</source>
        <translation>pared anterior</translation>
    </message>
    <message>
        <source>back wall</source>
        <translation>pared posterior</translation>
    </message>
    <message>
        <source>S%1</source>
        <comment>stitch number on the opened vessel</comment>
        <translation>P%1</translation>
    </message>
</context>
<context>
    <name>microsim::gui::PivotWizard</name>
    <message>
        <source>Pivot the tool</source>
        <translation>Pivote el instrumento</translation>
    </message>
    <message>
        <source>Hold the tip still in the divot and tilt the tool in every direction (at least %1°). Poses are collected automatically.</source>
        <translation>Mantenga la punta quieta en la cavidad e incline el instrumento en todas las direcciones (al menos %1°). Las poses se recogen automáticamente.</translation>
    </message>
    <message>
        <source>Spread %1° — enough</source>
        <translation>Dispersión %1° — suficiente</translation>
    </message>
    <message>
        <source>Spread %1° — tilt further</source>
        <translation>Dispersión %1° — incline más</translation>
    </message>
    <message>
        <source>Tip offset</source>
        <translation>Desplazamiento de la punta</translation>
    </message>
    <message>
        <source>Collect again</source>
        <translation>Recoger de nuevo</translation>
    </message>
    <message>
        <source>Tip (tool frame): %1, %2, %3 mm
Pivot (tracker frame): %4, %5, %6 mm
RMS error %7 mm, largest %8 mm
%9 poses, spread %10°</source>
        <translation>Punta (sistema del instrumento): %1, %2, %3 mm
Pivote (sistema del rastreador): %4, %5, %6 mm
Error RMS %7 mm, máximo %8 mm
%9 poses, dispersión %10°</translation>
    </message>
    <message>
        <source>Pivot calibration</source>
        <translation>Calibración por pivote</translation>
    </message>
    <message>
        <source>Tool</source>
        <translation>Instrumento</translation>
    </message>
    <message>
        <source>Choose the tracked device of the tool to calibrate.</source>
        <translation>Elija el dispositivo rastreado del instrumento que desea calibrar.</translation>
    </message>
    <message>
        <source>Left hand</source>
        <translation>Mano izquierda</translation>
    </message>
    <message>
        <source>Right hand</source>
        <translation>Mano derecha</translation>
    </message>
    <message>
        <source>Device:</source>
        <translation>Dispositivo:</translation>
    </message>
    <message>
        <source>Hand:</source>
        <translation>Mano:</translation>
    </message>
    <message>
        <source>Accepted: the error is within the threshold.</source>
        <translation>Aceptado: el error está dentro del umbral.</translation>
    </message>
    <message>
        <source>Too few poses: collect again.</source>
        <translation>Muy pocas poses: recoja de nuevo.</translation>
    </message>
    <message>
        <source>The tracker sent invalid poses: collect again.</source>
        <translation>El rastreador envió poses no válidas: recoja de nuevo.</translation>
    </message>
    <message>
        <source>The tool was not tilted enough: collect again.</source>
        <translation>El instrumento no se inclinó lo suficiente: recoja de nuevo.</translation>
    </message>
    <message>
        <source>The error is above the threshold (the tip slipped or the tool bent): collect again.</source>
        <translation>El error supera el umbral (la punta se deslizó o el instrumento se dobló): recoja de nuevo.</translation>
    </message>
</context>
<context>
    <name>microsim::gui::ProfileChooserDialog</name>
    <message>
        <source>Setup profile</source>
        <translation>Perfil de configuración</translation>
    </message>
    <message>
        <source>Use</source>
        <translation>Usar</translation>
    </message>
    <message>
        <source>Import…</source>
        <translation>Importar…</translation>
    </message>
    <message>
        <source>Export…</source>
        <translation>Exportar…</translation>
    </message>
    <message>
        <source>Delete</source>
        <translation>Eliminar</translation>
    </message>
    <message>
        <source>Import setup profile</source>
        <translation>Importar perfil de configuración</translation>
    </message>
    <message>
        <source>JSON (*.json)</source>
        <translation>JSON (*.json)</translation>
    </message>
    <message>
        <source>Export setup profile</source>
        <translation>Exportar perfil de configuración</translation>
    </message>
    <message>
        <source>%1 — %2 by %3</source>
        <translation>%1 — %2 por %3</translation>
    </message>
    <message>
        <source>unknown</source>
        <translation>desconocido</translation>
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
        <translation>No se puede leer %1.</translation>
    </message>
    <message>
        <source>The profile could not be stored: %1</source>
        <translation>No se pudo guardar el perfil: %1</translation>
    </message>
    <message>
        <source>The file is not a JSON document.</source>
        <translation>El archivo no es un documento JSON.</translation>
    </message>
    <message>
        <source>The file is not a microsim setup profile (%1).</source>
        <translation>El archivo no es un perfil de configuración de microsim (%1).</translation>
    </message>
    <message>
        <source>The field "%1" is missing.</source>
        <translation>Falta el campo «%1».</translation>
    </message>
    <message>
        <source>The field "%1" has the wrong type.</source>
        <translation>El campo «%1» tiene un tipo incorrecto.</translation>
    </message>
    <message>
        <source>The field "%1" has a value that is not allowed.</source>
        <translation>El campo «%1» tiene un valor no permitido.</translation>
    </message>
    <message>
        <source>The profile could not be read: %1</source>
        <translation>No se pudo leer el perfil: %1</translation>
    </message>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>No se puede escribir %1: %2</translation>
    </message>
</context>
<context>
    <name>microsim::gui::RegistrationWizard</name>
    <message>
        <source>Points</source>
        <translation>Puntos</translation>
    </message>
    <message>
        <source>Type each point's scene position, hold the tip on it and press Touch. Three fiducials at least; check points measure the error elsewhere.</source>
        <translation>Escriba la posición en la escena de cada punto, mantenga la punta sobre él y pulse «Tocar». Al menos tres fiduciales; los puntos de control miden el error en otro lugar.</translation>
    </message>
    <message>
        <source>Add point</source>
        <translation>Añadir punto</translation>
    </message>
    <message>
        <source>Touch</source>
        <translation>Tocar</translation>
    </message>
    <message>
        <source>Registration</source>
        <translation>Registro</translation>
    </message>
    <message>
        <source>FRE (fit): %1 mm RMS, %2 mm largest</source>
        <translation>FRE (ajuste): %1 mm RMS, máximo %2 mm</translation>
    </message>
    <message numerus="yes">
        <source>TRE (%n check point(s)): %1 mm RMS, %2 mm largest</source>
        <translation><numerusform>TRE (%n punto de control): %1 mm RMS, máximo %2 mm</numerusform><numerusform>TRE (%n puntos de control): %1 mm RMS, máximo %2 mm</numerusform></translation>
    </message>
    <message>
        <source>No check points: the TRE is unknown.</source>
        <translation>Sin puntos de control: el TRE es desconocido.</translation>
    </message>
    <message>
        <source>Role</source>
        <translation>Función</translation>
    </message>
    <message>
        <source>Scene x</source>
        <translation>Escena x</translation>
    </message>
    <message>
        <source>Scene y</source>
        <translation>Escena y</translation>
    </message>
    <message>
        <source>Scene z</source>
        <translation>Escena z</translation>
    </message>
    <message>
        <source>Tracker x</source>
        <translation>Rastreador x</translation>
    </message>
    <message>
        <source>Tracker y</source>
        <translation>Rastreador y</translation>
    </message>
    <message>
        <source>Tracker z</source>
        <translation>Rastreador z</translation>
    </message>
    <message>
        <source>Fiducial</source>
        <translation>Fiducial</translation>
    </message>
    <message>
        <source>Check point</source>
        <translation>Punto de control</translation>
    </message>
    <message>
        <source>Registered.</source>
        <translation>Registrado.</translation>
    </message>
    <message>
        <source>Touch at least three fiducials.</source>
        <translation>Toque al menos tres fiduciales.</translation>
    </message>
    <message>
        <source>Every point needs both positions.</source>
        <translation>Cada punto necesita ambas posiciones.</translation>
    </message>
    <message>
        <source>A position is not a number.</source>
        <translation>Una posición no es un número.</translation>
    </message>
    <message>
        <source>The fiducials lie on one line: spread them out.</source>
        <translation>Los fiduciales están en una línea: sepárelos.</translation>
    </message>
</context>
<context>
    <name>microsim::gui::ReplayControls</name>
    <message>
        <source>To the start (Home)</source>
        <translation>Al inicio (Inicio)</translation>
    </message>
    <message>
        <source>One frame back (Left)</source>
        <translation>Un fotograma atrás (Izquierda)</translation>
    </message>
    <message>
        <source>Play (Space)</source>
        <translation>Reproducir (Espacio)</translation>
    </message>
    <message>
        <source>One frame on (Right)</source>
        <translation>Un fotograma adelante (Derecha)</translation>
    </message>
    <message>
        <source>To the end (End)</source>
        <translation>Al final (Fin)</translation>
    </message>
    <message>
        <source>Replay position</source>
        <translation>Posición de la reproducción</translation>
    </message>
    <message>
        <source>Playback speed</source>
        <translation>Velocidad de reproducción</translation>
    </message>
    <message>
        <source>%1×</source>
        <translation>%1×</translation>
    </message>
    <message>
        <source>Stepping from the start: %p%</source>
        <translation>Recalculando desde el inicio: %p %</translation>
    </message>
    <message>
        <source>%1 / %2 s</source>
        <translation>%1 / %2 s</translation>
    </message>
    <message>
        <source>Pause (Space)</source>
        <translation>Pausa (Espacio)</translation>
    </message>
</context>
<context>
    <name>microsim::gui::ReplayTimeline</name>
    <message>
        <source>Pierces</source>
        <translation>Punciones</translation>
    </message>
    <message>
        <source>Grasps and releases</source>
        <translation>Agarres y liberaciones</translation>
    </message>
    <message>
        <source>Tissue: over-stretch, tears, cuts</source>
        <translation>Tejido: sobreestiramiento, desgarros, cortes</translation>
    </message>
    <message>
        <source>Errors</source>
        <translation>Errores</translation>
    </message>
    <message>
        <source>Pierce %1: the needle enters the wall</source>
        <translation>Punción %1: la aguja entra en la pared</translation>
    </message>
    <message>
        <source>Pierce %1: the needle leaves the wall</source>
        <translation>Punción %1: la aguja sale de la pared</translation>
    </message>
    <message>
        <source>Grasp</source>
        <translation>Agarre</translation>
    </message>
    <message>
        <source>Release</source>
        <translation>Liberación</translation>
    </message>
    <message>
        <source>Tissue over-stretched</source>
        <translation>Tejido sobreestirado</translation>
    </message>
    <message>
        <source>Tissue torn</source>
        <translation>Tejido desgarrado</translation>
    </message>
    <message>
        <source>Cut</source>
        <translation>Corte</translation>
    </message>
    <message>
        <source>Knot</source>
        <translation>Nudo</translation>
    </message>
    <message>
        <source>The forceps closed on nothing</source>
        <translation>La pinza se cerró sin agarrar nada</translation>
    </message>
    <message>
        <source>The suture broke</source>
        <translation>El hilo se rompió</translation>
    </message>
    <message>
        <source>Pierce %1: the suture slid out</source>
        <translation>Punción %1: el hilo se salió</translation>
    </message>
    <message>
        <source>Pierce %1: the needle left it before the thread</source>
        <translation>Punción %1: la aguja la dejó antes que el hilo</translation>
    </message>
    <message>
        <source>%1 (left hand), %2 s</source>
        <translation>%1 (mano izquierda), %2 s</translation>
    </message>
    <message>
        <source>%1 (right hand), %2 s</source>
        <translation>%1 (mano derecha), %2 s</translation>
    </message>
    <message>
        <source>%1, %2 s</source>
        <translation>%1, %2 s</translation>
    </message>
    <message>
        <source>Knots and thread cuts</source>
        <translation>Nudos y cortes del hilo</translation>
    </message>
    <message>
        <source>The scissors cut the thread</source>
        <translation>Las tijeras cortan el hilo</translation>
    </message>
    <message>
        <source>The needle was left too little thread to tie</source>
        <translation>A la aguja le quedó muy poco hilo para anudar</translation>
    </message>
    <message>
        <source>The knot slipped</source>
        <translation>El nudo se deslizó</translation>
    </message>
</context>
<context>
    <name>microsim::gui::ResultsPage</name>
    <message>
        <source>Metric</source>
        <translation>Métrica</translation>
    </message>
    <message>
        <source>Value</source>
        <translation>Valor</translation>
    </message>
    <message>
        <source>Points</source>
        <translation>Puntos</translation>
    </message>
    <message>
        <source>Advice</source>
        <translation>Consejo</translation>
    </message>
    <message>
        <source>Retry</source>
        <translation>Reintentar</translation>
    </message>
    <message>
        <source>Back to the lessons</source>
        <translation>Volver a las lecciones</translation>
    </message>
    <message>
        <source>&lt;b&gt;Pierce angles&lt;/b&gt; (0° = perpendicular; red entry, blue exit)</source>
        <translation>&lt;b&gt;Ángulos de punción&lt;/b&gt; (0° = perpendicular; rojo entrada, azul salida)</translation>
    </message>
    <message>
        <source>Test</source>
        <translation>Examen</translation>
    </message>
    <message>
        <source>Learn</source>
        <translation>Aprendizaje</translation>
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
        <translation>Sin calificar</translation>
    </message>
    <message>
        <source>&lt;span style='font-size:28pt'&gt;&lt;b&gt;%1&lt;/b&gt; / 100&lt;/span&gt;</source>
        <translation>&lt;span style='font-size:28pt'&gt;&lt;b&gt;%1&lt;/b&gt; / 100&lt;/span&gt;</translation>
    </message>
    <message>
        <source>&lt;span style='color:#1b7f3a; font-size:16pt'&gt;Passed&lt;/span&gt;</source>
        <translation>&lt;span style='color:#1b7f3a; font-size:16pt'&gt;Aprobado&lt;/span&gt;</translation>
    </message>
    <message>
        <source>&lt;span style='color:#b00020; font-size:16pt'&gt;Not passed yet&lt;/span&gt;</source>
        <translation>&lt;span style='color:#b00020; font-size:16pt'&gt;Aún no aprobado&lt;/span&gt;</translation>
    </message>
    <message>
        <source>Scored from an incomplete recording.</source>
        <translation>Calificado a partir de una grabación incompleta.</translation>
    </message>
    <message>
        <source>%1 (target %2)</source>
        <translation>%1 (objetivo %2)</translation>
    </message>
    <message>
        <source>Good.</source>
        <translation>Bien.</translation>
    </message>
</context>
<context>
    <name>microsim::gui::ReviewCharts</name>
    <message>
        <source>Score over attempts</source>
        <translation>Puntuación por intento</translation>
    </message>
    <message>
        <source>Attempt</source>
        <translation>Intento</translation>
    </message>
    <message>
        <source>Score</source>
        <translation>Puntuación</translation>
    </message>
    <message>
        <source>Pass mark</source>
        <translation>Nota de aprobado</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Target</source>
        <translation>Objetivo</translation>
    </message>
</context>
<context>
    <name>microsim::gui::ReviewPage</name>
    <message>
        <source>Export CSV…</source>
        <translation>Exportar CSV…</translation>
    </message>
    <message>
        <source>Refresh</source>
        <translation>Actualizar</translation>
    </message>
    <message>
        <source>Sign out</source>
        <translation>Cerrar sesión</translation>
    </message>
    <message>
        <source>Group:</source>
        <translation>Grupo:</translation>
    </message>
    <message>
        <source>Best score (attempts). ✓ passed, ★ proficient: the pass mark on two consecutive Test attempts. Double-click a cell for the history.</source>
        <translation>Mejor puntuación (intentos). ✓ aprobado, ★ competente: la nota de aprobado en dos intentos de examen consecutivos. Doble clic en una celda para ver el historial.</translation>
    </message>
    <message>
        <source>PDF report…</source>
        <translation>Informe PDF…</translation>
    </message>
    <message>
        <source>Trainee:</source>
        <translation>Residente:</translation>
    </message>
    <message>
        <source>Lesson:</source>
        <translation>Lección:</translation>
    </message>
    <message>
        <source>Overview</source>
        <translation>Resumen</translation>
    </message>
    <message>
        <source>History</source>
        <translation>Historial</translation>
    </message>
    <message>
        <source>Attempt</source>
        <translation>Intento</translation>
    </message>
    <message>
        <source>The history could not be read.</source>
        <translation>No se pudo leer el historial.</translation>
    </message>
    <message>
        <source>Instructor: %1</source>
        <translation>Instructor: %1</translation>
    </message>
    <message>
        <source>Trainee: %1</source>
        <translation>Residente: %1</translation>
    </message>
    <message>
        <source>All groups</source>
        <translation>Todos los grupos</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Trainee</source>
        <translation>Residente</translation>
    </message>
    <message>
        <source>Group</source>
        <translation>Grupo</translation>
    </message>
    <message>
        <source>That attempt could not be read.</source>
        <translation>No se pudo leer ese intento.</translation>
    </message>
    <message>
        <source>Only instructors can add notes.</source>
        <translation>Solo los instructores pueden añadir notas.</translation>
    </message>
    <message>
        <source>The note could not be stored.</source>
        <translation>No se pudo guardar la nota.</translation>
    </message>
    <message>
        <source>Note added.</source>
        <translation>Nota añadida.</translation>
    </message>
    <message>
        <source>Export attempts as CSV</source>
        <translation>Exportar intentos como CSV</translation>
    </message>
    <message>
        <source>CSV files (*.csv)</source>
        <translation>Archivos CSV (*.csv)</translation>
    </message>
    <message>
        <source>Exported the attempts to %1.</source>
        <translation>Intentos exportados a %1.</translation>
    </message>
    <message>
        <source>Choose a trainee first.</source>
        <translation>Elija primero un residente.</translation>
    </message>
    <message>
        <source>Save the report as PDF</source>
        <translation>Guardar el informe como PDF</translation>
    </message>
    <message>
        <source>PDF files (*.pdf)</source>
        <translation>Archivos PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Saved the report to %1.</source>
        <translation>Informe guardado en %1.</translation>
    </message>
    <message numerus="yes">
        <source>%n attempt(s): %1 finished, %2 abandoned</source>
        <translation><numerusform>%n intento: %1 terminados, %2 abandonados</numerusform><numerusform>%n intentos: %1 terminados, %2 abandonados</numerusform></translation>
    </message>
</context>
<context>
    <name>microsim::gui::ReviewReport</name>
    <message>
        <source>Cannot write %1: %2</source>
        <translation>No se puede escribir %1: %2</translation>
    </message>
    <message>
        <source>You may not export these attempts.</source>
        <translation>No tiene permiso para exportar estos intentos.</translation>
    </message>
    <message>
        <source>The export failed: %1</source>
        <translation>La exportación falló: %1</translation>
    </message>
    <message>
        <source>Training report: %1</source>
        <translation>Informe de formación: %1</translation>
    </message>
    <message>
        <source>Cannot write %1.</source>
        <translation>No se puede escribir %1.</translation>
    </message>
    <message>
        <source>Group: %1</source>
        <translation>Grupo: %1</translation>
    </message>
    <message>
        <source>Printed %1</source>
        <translation>Impreso el %1</translation>
    </message>
    <message>
        <source>Attempts</source>
        <translation>Intentos</translation>
    </message>
    <message>
        <source>#</source>
        <translation>N.º</translation>
    </message>
    <message>
        <source>Lesson</source>
        <translation>Lección</translation>
    </message>
    <message>
        <source>Started</source>
        <translation>Inicio</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Modo</translation>
    </message>
    <message>
        <source>Status</source>
        <translation>Estado</translation>
    </message>
    <message>
        <source>Score</source>
        <translation>Puntuación</translation>
    </message>
    <message>
        <source>Passed</source>
        <translation>Aprobado</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>sí</translation>
    </message>
    <message>
        <source>no</source>
        <translation>no</translation>
    </message>
    <message>
        <source>No attempts yet.</source>
        <translation>Aún no hay intentos.</translation>
    </message>
    <message>
        <source>End product</source>
        <translation>Resultado final</translation>
    </message>
    <message>
        <source>Each vessel cut along its axis and laid flat: 0° faces the microscope, the back wall is shaded.</source>
        <translation>Cada vaso cortado a lo largo de su eje y extendido: 0° mira al microscopio, la pared posterior está sombreada.</translation>
    </message>
    <message>
        <source>Attempt %1: %2, %3</source>
        <translation>Intento %1: %2, %3</translation>
    </message>
</context>
<context>
    <name>microsim::gui::ReviewText</name>
    <message>
        <source>Nothing of the task was done, so time and handling were not scored.</source>
        <translation>No se hizo nada de la tarea, así que el tiempo y el manejo no se puntuaron.</translation>
    </message>
    <message>
        <source>Took longer than the target time.</source>
        <translation>Tardó más que el tiempo objetivo.</translation>
    </message>
    <message>
        <source>The instruments travelled further than needed.</source>
        <translation>Los instrumentos recorrieron más de lo necesario.</translation>
    </message>
    <message>
        <source>Movements were jerky; aim for smooth, continuous motion.</source>
        <translation>Los movimientos fueron bruscos; busque un movimiento suave y continuo.</translation>
    </message>
    <message>
        <source>Long pauses with both hands still.</source>
        <translation>Pausas largas con ambas manos quietas.</translation>
    </message>
    <message>
        <source>The tissue was stretched too far.</source>
        <translation>El tejido se estiró demasiado.</translation>
    </message>
    <message>
        <source>Too many re-grasps.</source>
        <translation>Demasiados reagarres.</translation>
    </message>
    <message>
        <source>The wall was not passed with the needle.</source>
        <translation>La aguja no atravesó la pared.</translation>
    </message>
    <message>
        <source>The needle entered too obliquely; enter perpendicular to the wall.</source>
        <translation>La aguja entró demasiado oblicua; entre perpendicular a la pared.</translation>
    </message>
    <message>
        <source>The needle came out too obliquely; follow its curve.</source>
        <translation>La aguja salió demasiado oblicua; siga su curvatura.</translation>
    </message>
    <message>
        <source>Bites too far from the edge.</source>
        <translation>Pasos demasiado lejos del borde.</translation>
    </message>
    <message>
        <source>Bites too close to the edge.</source>
        <translation>Pasos demasiado cerca del borde.</translation>
    </message>
    <message>
        <source>Some passages did not go through the whole wall.</source>
        <translation>Algunos pasos no atravesaron toda la pared.</translation>
    </message>
    <message>
        <source>The two bites of a stitch differ in length.</source>
        <translation>Los dos pasos de un punto tienen longitudes distintas.</translation>
    </message>
    <message>
        <source>Not all stitches were completed.</source>
        <translation>No se completaron todos los puntos.</translation>
    </message>
    <message>
        <source>Too few stitches.</source>
        <translation>Muy pocos puntos.</translation>
    </message>
    <message>
        <source>More stitches than needed.</source>
        <translation>Más puntos de los necesarios.</translation>
    </message>
    <message>
        <source>The first stitches are not spaced 120° apart.</source>
        <translation>Los primeros puntos no están separados 120°.</translation>
    </message>
    <message>
        <source>The back wall was caught: the lumen would be closed.</source>
        <translation>Se atrapó la pared posterior: la luz quedaría cerrada.</translation>
    </message>
    <message>
        <source>The suture broke.</source>
        <translation>El hilo se rompió.</translation>
    </message>
    <message>
        <source>The tissue was torn or over-stretched.</source>
        <translation>El tejido se desgarró o se estiró en exceso.</translation>
    </message>
    <message>
        <source>%1: not measured in this attempt.</source>
        <translation>%1: no medido en este intento.</translation>
    </message>
    <message>
        <source>%1 too high.</source>
        <translation>%1 demasiado alto.</translation>
    </message>
    <message>
        <source>%1 too low.</source>
        <translation>%1 demasiado bajo.</translation>
    </message>
    <message>
        <source>Test</source>
        <translation>Examen</translation>
    </message>
    <message>
        <source>Learn</source>
        <translation>Aprendizaje</translation>
    </message>
    <message>
        <source>In progress</source>
        <translation>En curso</translation>
    </message>
    <message>
        <source>Finished</source>
        <translation>Terminado</translation>
    </message>
    <message>
        <source>Interrupted</source>
        <translation>Interrumpido</translation>
    </message>
    <message>
        <source>Abandoned</source>
        <translation>Abandonado</translation>
    </message>
    <message>
        <source>The wall was passed more often than needed.</source>
        <translation>La pared se atravesó más veces de las necesarias.</translation>
    </message>
    <message>
        <source>The needle was pushed rather than turned along its curve.</source>
        <translation>La aguja se empujó en lugar de girarla siguiendo su curva.</translation>
    </message>
    <message>
        <source>The needle was dragged sideways through the tissue.</source>
        <translation>La aguja se arrastró de lado por el tejido.</translation>
    </message>
    <message>
        <source>%1: not applicable to this input; not counted.</source>
        <translation>%1: no aplicable a esta entrada; no se cuenta.</translation>
    </message>
    <message>
        <source>Not every stitch was tied.</source>
        <translation>No se anudaron todos los puntos.</translation>
    </message>
    <message>
        <source>Knots were not square or surgeon's knots.</source>
        <translation>Los nudos no eran cuadrados ni de cirujano.</translation>
    </message>
    <message>
        <source>Knots had too few throws.</source>
        <translation>Los nudos tenían muy pocas vueltas.</translation>
    </message>
    <message>
        <source>Not every tail was cut.</source>
        <translation>No se cortaron todos los cabos.</translation>
    </message>
    <message>
        <source>Tails were left too long.</source>
        <translation>Los cabos quedaron demasiado largos.</translation>
    </message>
    <message>
        <source>Tails were cut too short.</source>
        <translation>Los cabos se cortaron demasiado cortos.</translation>
    </message>
    <message>
        <source>The finished anastomosis has lapses.</source>
        <translation>La anastomosis terminada tiene fallos.</translation>
    </message>
    <message>
        <source>A knot slipped: the stitch would open.</source>
        <translation>Un nudo se deslizó: el punto se abriría.</translation>
    </message>
    <message>
        <source>The suture line leaked under pressure.</source>
        <translation>La línea de sutura tuvo fuga bajo presión.</translation>
    </message>
</context>
<context>
    <name>microsim::gui::SignInPage</name>
    <message>
        <source>&lt;h2&gt;Who is practising?&lt;/h2&gt;</source>
        <translation>&lt;h2&gt;¿Quién practica?&lt;/h2&gt;</translation>
    </message>
    <message>
        <source>Trainee</source>
        <translation>Residente</translation>
    </message>
    <message>
        <source>Sign in</source>
        <translation>Entrar</translation>
    </message>
    <message>
        <source>Your name</source>
        <translation>Su nombre</translation>
    </message>
    <message>
        <source>Create and sign in</source>
        <translation>Crear y entrar</translation>
    </message>
    <message>
        <source>New trainee:</source>
        <translation>Nuevo residente:</translation>
    </message>
    <message>
        <source>Instructor</source>
        <translation>Instructor</translation>
    </message>
    <message>
        <source>Sign in as instructor</source>
        <translation>Entrar como instructor</translation>
    </message>
    <message>
        <source>Name</source>
        <translation>Nombre</translation>
    </message>
    <message>
        <source>Password</source>
        <translation>Contraseña</translation>
    </message>
    <message>
        <source>The history is unavailable: you can practise, but nothing will be stored.</source>
        <translation>El historial no está disponible: puede practicar, pero no se guardará nada.</translation>
    </message>
    <message>
        <source>Guest</source>
        <translation>Invitado</translation>
    </message>
    <message>
        <source>%1 (%2)</source>
        <translation>%1 (%2)</translation>
    </message>
    <message>
        <source>Type a name first.</source>
        <translation>Escriba primero un nombre.</translation>
    </message>
    <message>
        <source>A person called %1 already exists; pick them from the list.</source>
        <translation>Ya existe una persona llamada %1; elíjala en la lista.</translation>
    </message>
    <message>
        <source>The trainee could not be created (%1).</source>
        <translation>No se pudo crear el residente (%1).</translation>
    </message>
    <message>
        <source>Instructors need the history to sign in.</source>
        <translation>Los instructores necesitan el historial para entrar.</translation>
    </message>
    <message>
        <source>Unknown instructor or wrong password.</source>
        <translation>Instructor desconocido o contraseña incorrecta.</translation>
    </message>
    <message>
        <source>No instructor has been set up in this history yet. Create the first one: they can then add instructors and trainees.</source>
        <translation>Este historial aún no tiene ningún instructor. Cree el primero: después podrá añadir instructores y residentes.</translation>
    </message>
    <message>
        <source>Create instructor and sign in</source>
        <translation>Crear instructor e iniciar sesión</translation>
    </message>
</context>
<context>
    <name>microsim::gui::TrackerStatusWidget</name>
    <message>
        <source>Tracker connected</source>
        <translation>Rastreador conectado</translation>
    </message>
    <message>
        <source>Tracker not connected</source>
        <translation>Rastreador no conectado</translation>
    </message>
    <message>
        <source>%1 Hz</source>
        <translation>%1 Hz</translation>
    </message>
    <message numerus="yes">
        <source>%n dropped</source>
        <translation><numerusform>%n descartado</numerusform><numerusform>%n descartados</numerusform></translation>
    </message>
    <message>
        <source>No tracker</source>
        <translation>Sin rastreador</translation>
    </message>
</context>
<context>
    <name>microsim::gui::TraineeHistoryView</name>
    <message>
        <source>Attempt</source>
        <translation>Intento</translation>
    </message>
    <message>
        <source>Finished</source>
        <translation>Terminado</translation>
    </message>
    <message>
        <source>Mode</source>
        <translation>Modo</translation>
    </message>
    <message>
        <source>Score</source>
        <translation>Puntuación</translation>
    </message>
    <message>
        <source>Passed</source>
        <translation>Aprobado</translation>
    </message>
    <message>
        <source>No finished attempts in this lesson yet.</source>
        <translation>Aún no hay intentos terminados en esta lección.</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>sí</translation>
    </message>
    <message>
        <source>no</source>
        <translation>no</translation>
    </message>
</context>
<context>
    <name>microsim::gui::Viewport</name>
    <message>
        <source>F1: keys</source>
        <translation>F1: teclas</translation>
    </message>
    <message>
        <source>Left hand active</source>
        <translation>Mano izquierda activa</translation>
    </message>
    <message>
        <source>Right hand active</source>
        <translation>Mano derecha activa</translation>
    </message>
    <message>
        <source>Side view</source>
        <translation>Vista lateral</translation>
    </message>
    <message>
        <source>Left hand: %1 · right hand: %2</source>
        <translation>Mano izquierda: %1 · mano derecha: %2</translation>
    </message>
    <message>
        <source>nothing</source>
        <translation>nada</translation>
    </message>
    <message>
        <source>forceps</source>
        <translation>pinzas</translation>
    </message>
    <message>
        <source>needle holder</source>
        <translation>portaagujas</translation>
    </message>
    <message>
        <source>scalpel</source>
        <translation>bisturí</translation>
    </message>
    <message>
        <source>scissors</source>
        <translation>tijeras</translation>
    </message>
</context>
<context>
    <name>microsim::gui::settings::SettingsDialog</name>
    <message>
        <source>Settings</source>
        <translation>Ajustes</translation>
    </message>
    <message>
        <source>Scene default</source>
        <translation>Valor de la escena</translation>
    </message>
    <message>
        <source>Takes effect at the next start.</source>
        <translation>Se aplica en el próximo inicio.</translation>
    </message>
</context>
<context>
    <name>microsim::gui::settings::Tunables</name>
    <message>
        <source>As the lesson's scene says</source>
        <translation>Según la escena de la lección</translation>
    </message>
    <message>
        <source>Quasi-static (the paper's)</source>
        <translation>Cuasiestático (el del artículo)</translation>
    </message>
    <message>
        <source>Newton with multigrid</source>
        <translation>Newton con multimalla</translation>
    </message>
    <message>
        <source>Implicit Euler</source>
        <translation>Euler implícito</translation>
    </message>
    <message>
        <source>Tissue solver</source>
        <translation>Resolutor del tejido</translation>
    </message>
    <message>
        <source>The tissue solver of live attempts; graded replays use the same one.</source>
        <translation>El resolutor del tejido en los intentos en vivo; las reproducciones calificadas usan el mismo.</translation>
    </message>
    <message>
        <source>Iteration budget</source>
        <translation>Presupuesto de iteraciones</translation>
    </message>
    <message>
        <source>Solver iterations per step; 0 keeps the scene's.</source>
        <translation>Iteraciones del resolutor por paso; 0 mantiene las de la escena.</translation>
    </message>
    <message>
        <source>Mono</source>
        <translation>Mono</translation>
    </message>
    <message>
        <source>Quad-buffer stereo</source>
        <translation>Estéreo de cuádruple búfer</translation>
    </message>
    <message>
        <source>Anaglyph (red/cyan)</source>
        <translation>Anaglifo (rojo/cian)</translation>
    </message>
    <message>
        <source>Side by side</source>
        <translation>Lado a lado</translation>
    </message>
    <message>
        <source>Stereo</source>
        <translation>Estéreo</translation>
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
        <translation>Asignación de teclas</translation>
    </message>
    <message>
        <source>Which letter keys move the tools; the arrows and Space stay the same.</source>
        <translation>Qué letras mueven los instrumentos; las flechas y la barra espaciadora no cambian.</translation>
    </message>
    <message>
        <source>Millimetres</source>
        <translation>Milímetros</translation>
    </message>
    <message>
        <source>Micrometres</source>
        <translation>Micrómetros</translation>
    </message>
    <message>
        <source>Length units</source>
        <translation>Unidad de longitud</translation>
    </message>
    <message>
        <source>Units of lengths on the results page.</source>
        <translation>Unidad de las longitudes en la página de resultados.</translation>
    </message>
    <message>
        <source>System default</source>
        <translation>Predeterminado del sistema</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Idioma</translation>
    </message>
    <message>
        <source>The interface language.</source>
        <translation>El idioma de la interfaz.</translation>
    </message>
    <message>
        <source>How the microscope's two eyes are shown. Quad-buffer stereo is offered only where the display has left and right buffers.</source>
        <translation>Cómo se muestran los dos ojos del microscopio. El estéreo de cuádruple búfer solo se ofrece donde la pantalla tiene búferes izquierdo y derecho.</translation>
    </message>
</context>
<context>
    <name>microsim::i18n::EndProductWords</name>
    <message>
        <source>suture-line disruption</source>
        <translation>interrupción de la línea de sutura</translation>
    </message>
    <message>
        <source>back-wall stitch</source>
        <translation>punto en la pared posterior</translation>
    </message>
    <message>
        <source>oblique stitch</source>
        <translation>punto oblicuo</translation>
    </message>
    <message>
        <source>wide bite</source>
        <translation>paso demasiado ancho</translation>
    </message>
    <message>
        <source>partial-thickness bite</source>
        <translation>paso de espesor parcial</translation>
    </message>
    <message>
        <source>unequal spacing</source>
        <translation>separación desigual</translation>
    </message>
    <message>
        <source>wall tear</source>
        <translation>desgarro de la pared</translation>
    </message>
    <message>
        <source>over-tight stitch</source>
        <translation>punto demasiado apretado</translation>
    </message>
    <message>
        <source>thread in the lumen</source>
        <translation>hilo en la luz</translation>
    </message>
    <message>
        <source>large edge overlap</source>
        <translation>gran solapamiento de los bordes</translation>
    </message>
</context>
<context>
    <name>microsim::tracking::GamepadSource</name>
    <message>
        <source>The game controller cannot be read: SDL did not start (%1).</source>
        <translation>No se puede leer el mando: SDL no se inició (%1).</translation>
    </message>
    <message>
        <source>No game controller found: connect one (USB or Bluetooth) and try again.</source>
        <translation>No se encontró ningún mando: conecte uno (USB o Bluetooth) y vuelva a intentarlo.</translation>
    </message>
    <message>
        <source>The game controller %1 was disconnected.</source>
        <translation>El mando %1 se desconectó.</translation>
    </message>
</context>
<context>
    <name>microsim::tracking::ManualSource</name>
    <message>
        <source>Tab — switch hand</source>
        <translation>Tab — cambiar de mano</translation>
    </message>
    <message>
        <source>A / D — move left / right</source>
        <translation>A / D — mover a la izquierda / derecha</translation>
    </message>
    <message>
        <source>W / S — move up / down</source>
        <translation>W / S — mover arriba / abajo</translation>
    </message>
    <message>
        <source>Q / E — move away / toward you</source>
        <translation>Q / E — alejar / acercar</translation>
    </message>
    <message>
        <source>← / → — turn the tool</source>
        <translation>← / → — girar el instrumento</translation>
    </message>
    <message>
        <source>↑ / ↓ — tilt the tool</source>
        <translation>↑ / ↓ — inclinar el instrumento</translation>
    </message>
    <message>
        <source>Space (hold) — close the jaws</source>
        <translation>Espacio (mantener) — cerrar las mordazas</translation>
    </message>
    <message>
        <source>Shift — fine steps</source>
        <translation>Mayús — pasos finos</translation>
    </message>
    <message>
        <source>R — reset the tools</source>
        <translation>R — reiniciar los instrumentos</translation>
    </message>
    <message>
        <source>F1 — show or hide this help</source>
        <translation>F1 — mostrar u ocultar esta ayuda</translation>
    </message>
    <message>
        <source>Z / X — turn the held needle back / forward along its curve</source>
        <translation>Z / X — girar la aguja sujeta hacia atrás / adelante a lo largo de su curva</translation>
    </message>
    <message>
        <source>C / V — close / open the jaws a step</source>
        <translation>C / V — cerrar / abrir las mandíbulas un paso</translation>
    </message>
    <message>
        <source>Left drag — move the tool in the view plane; wheel — move it in depth</source>
        <translation>Arrastrar con el botón izquierdo — mover el instrumento en el plano de la vista; rueda — moverlo en profundidad</translation>
    </message>
    <message>
        <source>Ctrl + left drag or Ctrl + wheel — turn the held needle along its curve</source>
        <translation>Ctrl + arrastrar con el izquierdo o Ctrl + rueda — girar la aguja sujeta a lo largo de su curva</translation>
    </message>
    <message>
        <source>Ctrl + left drag without a needle — turn the tool</source>
        <translation>Ctrl + arrastrar con el izquierdo sin aguja — girar el instrumento</translation>
    </message>
    <message>
        <source>Right drag down / up — close / open the jaws; right click — close or open them</source>
        <translation>Arrastrar con el derecho hacia abajo / arriba — cerrar / abrir las mandíbulas; clic derecho — cerrarlas o abrirlas</translation>
    </message>
    <message>
        <source>Middle drag or Shift + left drag — orbit; Shift + middle drag — pan</source>
        <translation>Arrastrar con el central o Mayús + arrastrar con el izquierdo — orbitar; Mayús + arrastrar con el central — desplazar</translation>
    </message>
    <message>
        <source>Shift + wheel — zoom; Alt + wheel — focus</source>
        <translation>Mayús + rueda — zoom; Alt + rueda — enfocar</translation>
    </message>
    <message>
        <source>Home — microscope view; 1 / 2 / 3 — top / oblique / side view</source>
        <translation>Inicio — vista del microscopio; 1 / 2 / 3 — vista superior / oblicua / lateral</translation>
    </message>
    <message>
        <source>T — take up the scissors or the forceps (the jaw keys and buttons close either)</source>
        <translation>T — tomar las tijeras o las pinzas (las teclas y botones de las ramas cierran ambas)</translation>
    </message>
</context>
<context>
    <name>microsim::tracking::SpacenavSource</name>
    <message>
        <source>No 3D mouse: spacenavd, the 3D mouse's daemon, is not running or cannot be reached (install and start spacenavd, then try again).</source>
        <translation>No hay ratón 3D: spacenavd, el servicio del ratón 3D, no está en marcha o no responde (instale e inicie spacenavd y vuelva a intentarlo).</translation>
    </message>
    <message>
        <source>The 3D mouse's daemon (spacenavd) closed the connection.</source>
        <translation>El servicio del ratón 3D (spacenavd) cerró la conexión.</translation>
    </message>
</context>
</TS>