<?xml version='1.0' encoding='utf-8'?>
<TS version="2.1" language="es">
<context>
    <name>Cli</name>
    <message>
        <source>microsim-cli: this build has no benchmarks (configure with -DMICROSIM_BUILD_BENCHMARKS=ON)</source>
        <translation>microsim-cli: esta compilación no incluye benchmarks (configure con -DMICROSIM_BUILD_BENCHMARKS=ON)</translation>
    </message>
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
        <source>microsim-cli bench: name one benchmark (see --list)</source>
        <translation>microsim-cli bench: indique un solo benchmark (vea --list)</translation>
    </message>
    <message>
        <source>microsim-cli bench: unknown benchmark '%1' (see --list)</source>
        <translation>microsim-cli bench: benchmark desconocido «%1» (vea --list)</translation>
    </message>
    <message>
        <source>microsim-cli bench: cannot write %1: %2</source>
        <translation>microsim-cli bench: no se puede escribir %1: %2</translation>
    </message>
    <message>
        <source>microsim-cli bench: '%1' has no curves to plot</source>
        <translation>microsim-cli bench: «%1» no tiene curvas que dibujar</translation>
    </message>
    <message>
        <source>microsim-cli bench: cannot write the plot %1</source>
        <translation>microsim-cli bench: no se puede escribir el gráfico %1</translation>
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
</context>
<context>
    <name>microsim::gui::MainWindow</name>
    <message>
        <source>microsim — micro-anastomosis trainer</source>
        <translation>microsim — entrenador de microanastomosis</translation>
    </message>
    <message>
        <source>Drag to orbit the microscope, wheel to zoom.</source>
        <translation>Arrastre para girar el microscopio; la rueda acerca y aleja.</translation>
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
        <source>&amp;Language</source>
        <translation>&amp;Idioma</translation>
    </message>
    <message>
        <source>System default</source>
        <translation>Predeterminado del sistema</translation>
    </message>
    <message>
        <source>English</source>
        <translation>Inglés</translation>
    </message>
    <message>
        <source>German</source>
        <translation>Alemán</translation>
    </message>
    <message>
        <source>Spanish</source>
        <translation>Español</translation>
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
</context>
</TS>